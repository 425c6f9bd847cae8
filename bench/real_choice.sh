#!/usr/bin/env bash
# Float against double, side by side in one run: the evidence for the default RTLAB_REAL.
# Builds both presets, then alternates the two builds' runs so that both see the same load.
#
#   bench/real_choice.sh [rounds]
set -euo pipefail
cd "$(dirname "$0")/.."
rounds=${1:-5}
for p in release float; do
    cmake --preset "$p" -DRTLAB_BENCH=ON >/dev/null
    cmake --build --preset "$p" -j "$(nproc)" --target bench_sphere_roots ch02 >/dev/null
done
echo "== accuracy and cost of the root formulas"
for p in release float; do build/$p/bin/bench_sphere_roots 200000 "$rounds"; echo; done

echo "== whole renders: ch02 far-sphere, 800x600, 16 spp, 1 thread (seconds, best of $rounds)"
best() { sort -g | head -1; }
declare -A times
for ((r = 0; r < rounds; r++)); do
    for p in release float; do
        s=$(build/$p/bin/ch02 --scene far-sphere --width 800 --height 600 --spp 16 --threads 1 --stats \
            -o "/tmp/rtlab-bench-$p.pfm" | sed -E 's/.*"seconds":([0-9.e-]+).*/\1/')
        times[$p]+="$s"$'\n'
    done
done
d=$(printf '%s' "${times[release]}" | best)
f=$(printf '%s' "${times[float]}" | best)
echo "double $d s, float $f s, float/double = $(awk -v a="$f" -v b="$d" 'BEGIN{printf "%.3f", a/b}')"
