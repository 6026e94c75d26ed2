"""Builds the module sph._sph with the project's CMake and puts it in the package (pyproject.toml).

SPH_BUILD_DIR: the CMake build folder (default build-python/); one the scripts built already
(build/) makes the install take seconds. CMAKE_ARGS: more -D options (say -DSPH_WITH_CUDA=ON).
"""
import os
import pathlib
import shlex
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build = pathlib.Path(os.environ.get("SPH_BUILD_DIR", ROOT / "build-python")).resolve()
        # A folder configured already (the scripts' build/) is built as it is: its interpreter
        # stays the one its tests run with.
        if not (build / "CMakeCache.txt").exists():
            subprocess.run(["cmake", "-S", str(ROOT), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release",
                            "-DSPH_WITH_PYTHON=ON", f"-DPython_EXECUTABLE={sys.executable}",
                            "-DSPH_BUILD_TESTS=OFF", "-DSPH_BUILD_APPS=OFF",
                            "-DSPH_BUILD_BENCHMARKS=OFF", "-DSPH_BUILD_EXAMPLES=OFF",
                            "-DSPH_WITH_CUDA=OFF"] + shlex.split(os.environ.get("CMAKE_ARGS", "")),
                           check=True)
        subprocess.run(["cmake", "--build", str(build), "--target", "sph_python", "-j",
                        str(os.cpu_count() or 2)], check=True)
        tag = f"cpython-{sys.version_info.major}{sys.version_info.minor}"
        built = sorted((build / "python" / "sph").glob(f"_sph.{tag}*.so"))
        if not built:
            raise RuntimeError(f"the CMake build in {build} made no sph/_sph.{tag}*.so: was it "
                               f"configured for another Python than {sys.executable}?")
        target = pathlib.Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        self.copy_file(str(built[0]), str(target))


# setuptools keeps its own files apart from the CMake build folders.
setup(ext_modules=[Extension("sph._sph", sources=[])], cmdclass={"build_ext": CMakeBuild},
      options={"build": {"build_base": str(ROOT / "build-python" / "setuptools")}})
