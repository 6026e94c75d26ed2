#!/usr/bin/env bash
# scripts/plot-solvers on a few lines of `sph bench --solver wcsph,dfsph --json`: box drop sizes
# for both solvers, a scene's points, a repeated size; and a file with no solver lines, which it
# refuses.
# Usage: plot_solvers_test.sh <sph source dir> <scratch dir>
set -euo pipefail

if [ "$#" -ne 2 ]; then
  echo "usage: $0 <sph source dir> <scratch dir>" >&2
  exit 2
fi
plot="$1/scripts/plot-solvers"
scratch="$2"
rm -rf "$scratch"
mkdir -p "$scratch"

fail() {
  echo "plot-solvers test FAILED: $*" >&2
  exit 1
}

cat >"$scratch/bench.jsonl" <<'JSON'
{"scene":"box_drop","particles":16384,"solver":"wcsph","real_time_factor":0.14}
{"scene":"box_drop","particles":65536,"solver":"wcsph","real_time_factor":0.026}
{"scene":"box_drop","particles":16384,"solver":"dfsph","real_time_factor":0.9}
{"scene":"box_drop","particles":16384,"solver":"dfsph","real_time_factor":1.1}
{"scene":"box_drop","particles":65536,"solver":"dfsph","real_time_factor":0.23}
{"scene":"dam_break","particles":67626,"solver":"dfsph","real_time_factor":0.02}
{"scene":"dam_break","particles":67626,"solver":"wcsph","real_time_factor":0.013}
JSON
"$plot" "$scratch/bench.jsonl" -o "$scratch/plot.png" || fail "exit status $?"
[ "$(head -c 8 "$scratch/plot.png" | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ] ||
  fail "$scratch/plot.png is not a PNG"

echo '{"scene":"box_drop","particles":4096,"ms_per_step":0.8}' >"$scratch/no_solver.jsonl"
if "$plot" "$scratch/no_solver.jsonl" -o "$scratch/none.png" 2>/dev/null; then
  fail "a file without solver lines was plotted"
fi
echo "plot-solvers test passed"
