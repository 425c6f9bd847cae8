#!/usr/bin/env bash
# Render throughput of chapter binaries, side by side in one run: for each scene and thread
# count, every binary renders in turn, ROUNDS times, and the fastest of its rounds counts
# (the machines are shared; the minimum is the least disturbed). The ratio is against the
# first binary directory given.
#
#   bench/throughput.sh [--rounds N] BIN_DIR [BIN_DIR...]
#   e.g. bench/throughput.sh /tmp/old/build/release/bin build/release/bin
#
# Scenes (bench/scenes/): spheres488 (a grid of small spheres on a huge ground sphere,
# 400x225, 10 spp) and meshes (1024 brute-force triangles, 400x225, 2 spp).
set -euo pipefail
cd "$(dirname "$0")/.."
rounds=3
if [[ "${1-}" == --rounds ]]; then rounds=$2; shift 2; fi
(($#)) || { echo "usage: bench/throughput.sh [--rounds N] BIN_DIR [BIN_DIR...]" >&2; exit 2; }
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

printf '%-11s %-7s %-40s %8s %9s %6s\n' scene threads binary seconds Mrays/s ratio
for case in "spheres488 10" "meshes 2"; do
    read -r scene spp <<<"$case"
    for threads in 1 2; do
        declare -A best=()
        for ((r = 0; r < rounds; r++)); do
            for dir in "$@"; do
                s=$("$dir/ch05" --scene "bench/scenes/$scene.json" --width 400 --height 225 --spp "$spp" \
                    --threads "$threads" --seed 1 --stats -o "$out/img.pfm" |
                    sed -E 's/.*"seconds":([0-9.e+-]+).*/\1/')
                if [[ -z "${best[$dir]-}" ]] || awk "BEGIN{exit !($s < ${best[$dir]})}"; then best[$dir]=$s; fi
            done
        done
        base=${best[$1]}
        for dir in "$@"; do
            awk -v sc="$scene" -v th="$threads" -v d="$dir" -v s="${best[$dir]}" -v b="$base" \
                -v rays=$((400 * 225 * spp)) \
                'BEGIN{printf "%-11s %-7s %-40s %8.3f %9.3f %6.2f\n", sc, th, d, s, rays / s / 1e6, b / s}'
        done
        unset best
    done
done
