#!/usr/bin/env bash
# Runs one libFuzzer target over its seeds and regressions.
#
#   run.sh BIN_DIR ROOT WORK TARGET short          a few seconds: what ./lab test runs
#   run.sh BIN_DIR ROOT WORK TARGET long SECONDS   ./lab fuzz: keeps its corpus in WORK/corpus
#
# Seeds are the repository's own inputs (scene files, appendix A's examples, golden images,
# tests/fuzz/seeds/), assembled afresh in WORK/seeds/TARGET each run. A crash is saved as
# WORK/crashes/TARGET-*: fix it, then keep the input in tests/fuzz/regressions/TARGET/ so
# every later run replays it.
set -euo pipefail
bin=$1 root=$2 work=$3 target=$4 mode=$5 seconds=${6-60}
seeds=$work/seeds/$target
rm -rf "$seeds"
mkdir -p "$seeds" "$work/corpus/$target" "$work/crashes"

case $target in
scene | json)
    for f in "$root"/chapters/*/scenes/*.json "$root"/bench/scenes/*.json "$root"/tests/data/*.json \
        "$root"/tests/data/bad/*.json; do
        cp "$f" "$seeds/$(basename "$(dirname "$f")")-$(basename "$f")"
    done
    # Appendix A's examples, one file each.
    awk -v dir="$seeds" '/^```json$/ {n++; on=1; next} /^```$/ {on=0} on {print > (dir "/appendix-" n ".json")}' \
        "$root/book/appendix-a-scene-format.md"
    ;;
obj)
    cp "$root"/tests/fuzz/seeds/obj/* "$seeds"/
    # The Cornell box of ../shared, where it is (read in place, never copied into the lab).
    cp "$root"/../shared/assets/meshes/CornellBox-Original.obj "$seeds"/ 2>/dev/null || true
    ;;
image)
    cp "$root"/tests/golden/ch01/*.png "$seeds"/
    # A 2x1 PFM: little-endian floats.
    printf 'PF\n2 1\n-1.0\n' > "$seeds/two.pfm"
    printf '\x00\x00\x80\x3f\x00\x00\x00\x3f\x00\x00\x00\x00\x00\x00\x80\x3e\x00\x00\x00\x00\x00\x00\x80\x3f' >> "$seeds/two.pfm"
    ;;
cli)
    cp "$root"/tests/fuzz/seeds/cli/* "$seeds"/
    ;;
*)
    echo "run.sh: unknown target '$target'" >&2
    exit 2
    ;;
esac

options=(-close_fd_mask=3 -timeout=10 -rss_limit_mb=2048 -max_len=16384 -print_final_stats=1
    "-artifact_prefix=$work/crashes/$target-")
if [[ $mode == short ]]; then
    # A fresh corpus each time, so the test takes the same few seconds on every run.
    rm -rf "$work/corpus/$target"
    mkdir -p "$work/corpus/$target"
    options+=(-max_total_time=8)
else
    options+=("-max_total_time=$seconds")
fi
inputs=("$work/corpus/$target" "$seeds")
[[ -d $root/tests/fuzz/regressions/$target ]] && inputs+=("$root/tests/fuzz/regressions/$target")
log=$work/$target.log
if ! "$bin/fuzz_$target" "${options[@]}" "${inputs[@]}" > "$log" 2>&1; then
    tail -40 "$log"
    echo "fuzz_$target: FAILED; the input is in $work/crashes/ (keep it in tests/fuzz/regressions/$target/)"
    exit 1
fi
runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
echo "fuzz_$target: ${runs:-?} executions, no crash, leak or sanitizer report"
