#!/usr/bin/env bash
# Installs a built sph into a scratch prefix, then builds and runs a separate project that
# finds it with find_package(sph) (tests/package/consumer).
# Usage: package_test.sh <sph source dir> <sph build dir> <scratch dir>
set -euo pipefail

if [ "$#" -ne 3 ]; then
  echo "usage: $0 <sph source dir> <sph build dir> <scratch dir>" >&2
  exit 2
fi
src="$1"
build="$2"
scratch="$3"
prefix="$scratch/prefix"
consumer_src="$src/tests/package/consumer"
consumer_build="$scratch/consumer-build"

fail() {
  echo "package test FAILED: $*" >&2
  exit 1
}

[ -f "$build/CMakeCache.txt" ] || fail "$build is not a configured CMake build directory"
[ -f "$consumer_src/CMakeLists.txt" ] || fail "consumer project not found at $consumer_src"

rm -rf "$prefix" "$consumer_build"
mkdir -p "$scratch"

echo "-- installing $build into $prefix"
cmake --install "$build" --prefix "$prefix" || fail "cmake --install $build --prefix $prefix"

# What the package must contain.
libdir=""
for d in lib lib64 lib/x86_64-linux-gnu lib/aarch64-linux-gnu; do
  if [ -f "$prefix/$d/libsph.a" ] || [ -f "$prefix/$d/libsph.so" ]; then libdir="$d"; break; fi
done
[ -n "$libdir" ] || fail "no libsph.a (or libsph.so) installed under $prefix/lib*"
for h in sph/simulation.hpp sph/scene.hpp sph/scene_file.hpp sph/core/options.hpp; do
  [ -f "$prefix/include/$h" ] || fail "header $h not installed under $prefix/include"
done
for f in sphConfig.cmake sphConfigVersion.cmake sphTargets.cmake; do
  [ -f "$prefix/$libdir/cmake/sph/$f" ] || fail "$f not installed in $prefix/$libdir/cmake/sph"
done
echo "-- installed: $libdir/libsph.*, include/sph/, $libdir/cmake/sph/"

# A sanitizer build's static library holds instrumented code: the consumer must link the
# sanitizer runtimes too.
extra=()
sanitize="$(sed -n 's/^SPH_SANITIZE:[A-Z]*=//p' "$build/CMakeCache.txt")"
case "${sanitize^^}" in
  ON|TRUE|YES|Y|1)
    extra+=("-DCMAKE_CXX_FLAGS=-fsanitize=address,undefined"
            "-DCMAKE_EXE_LINKER_FLAGS=-fsanitize=address,undefined")
    echo "-- $build has SPH_SANITIZE=ON: the consumer links with -fsanitize=address,undefined"
    ;;
esac
build_type="$(sed -n 's/^CMAKE_BUILD_TYPE:[A-Z]*=//p' "$build/CMakeCache.txt")"
[ -n "$build_type" ] || build_type=Release
compiler="$(sed -n 's/^CMAKE_CXX_COMPILER:[A-Z]*=//p' "$build/CMakeCache.txt")"
[ -z "$compiler" ] || extra+=("-DCMAKE_CXX_COMPILER=$compiler")

echo "-- configuring the consumer in $consumer_build"
cmake -S "$consumer_src" -B "$consumer_build" -DCMAKE_BUILD_TYPE="$build_type" \
      -DCMAKE_PREFIX_PATH="$prefix" "${extra[@]}" \
  || fail "configuring the consumer: find_package(sph) against $prefix"

echo "-- building the consumer"
cmake --build "$consumer_build" || fail "building the consumer against the installed sph"

echo "-- running the consumer"
"$consumer_build/consumer" || fail "the consumer ran but exited with status $?"

if [ -f "$prefix/include/sph/bullet_engine.hpp" ]; then  # sph was built with its Bullet adapter
  [ -x "$consumer_build/consumer_bullet" ] ||
    fail "sph::bullet is installed but the consumer could not build against it"
  echo "-- running the Bullet consumer"
  "$consumer_build/consumer_bullet" || fail "the Bullet consumer ran but exited with status $?"
fi

echo "package test passed"
