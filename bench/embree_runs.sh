#!/usr/bin/env bash
# The Embree comparison, repeated: RUNS runs of bench_embree, each a process of its own, the
# first printed in full and then, for every input and row, the median ratio of all runs
# with the lowest and highest. One run is not enough on a shared machine: here a process
# lands as a whole in a faster or a slower mode, and runs differ by ±0.05 or more, so
# repeating inside one process would not sample what a second process sees.
#
#   bench/embree_runs.sh BIN RUNS [MESH.obj ...]
set -euo pipefail
(($# >= 2)) || { echo "usage: bench/embree_runs.sh BIN RUNS [MESH.obj ...]" >&2; exit 2; }
bin=$1 runs=$2
shift 2
[[ $runs =~ ^[1-9][0-9]*$ ]] || { echo "bench/embree_runs.sh: RUNS must be a whole number from 1, not '$runs'" >&2; exit 2; }
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for ((i = 1; i <= runs; i++)); do
    echo "run $i of $runs" >&2
    "$bin" --by-class "$@" >"$out/run$i.txt"
done
cat "$out/run1.txt"
echo
python3 "$(dirname "$0")/embree_medians.py" "$out"/run*.txt
