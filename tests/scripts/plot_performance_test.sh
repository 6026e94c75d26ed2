#!/usr/bin/env bash
# scripts/plot-performance on a few lines of `sph bench --json`: two CPU runs, a CUDA run and a
# scene file's line, which it leaves out; and a file with no box drop, which it refuses.
# Usage: plot_performance_test.sh <sph source dir> <scratch dir>
set -euo pipefail

if [ "$#" -ne 2 ]; then
  echo "usage: $0 <sph source dir> <scratch dir>" >&2
  exit 2
fi
plot="$1/scripts/plot-performance"
scratch="$2"
rm -rf "$scratch"
mkdir -p "$scratch"

fail() {
  echo "plot-performance test FAILED: $*" >&2
  exit 1
}

cat >"$scratch/bench.jsonl" <<'JSON'
{"scene":"box_drop","particles":4096,"backend":"cpu","threads":2,"ms_per_step":0.8}
{"scene":"box_drop","particles":16384,"backend":"cpu","threads":2,"ms_per_step":2.6}
{"scene":"box_drop","particles":16384,"backend":"cpu","threads":2,"ms_per_step":3.1}
{"scene":"artery_squeeze","particles":9000,"backend":"cpu","threads":2,"ms_per_step":7.0}
{"scene":"box_drop","particles":65536,"backend":"cuda","threads":2,"ms_per_step":0.9}
JSON
"$plot" "$scratch/bench.jsonl" -o "$scratch/plot.png" || fail "exit status $?"
[ "$(head -c 8 "$scratch/plot.png" | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ] ||
  fail "$scratch/plot.png is not a PNG"

grep artery_squeeze "$scratch/bench.jsonl" >"$scratch/no_box_drop.jsonl"
if "$plot" "$scratch/no_box_drop.jsonl" -o "$scratch/none.png" 2>/dev/null; then
  fail "a file without box_drop lines was plotted"
fi
echo "plot-performance test passed"
