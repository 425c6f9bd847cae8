#!/usr/bin/env bash
# Where rtlab's time goes on the sphere scene with the glass made mirrors (the scene closest
# to Tachyon's ground, book §10.10): callgrind's instructions per function, per ray of the
# render (camera, shadow and reflection rays together) and in all.
#
#   bench/peers/profile.sh BIN_DIR [WxH]     e.g. bench/peers/profile.sh build/profile/bin 640x360
#
# BIN_DIR must be a build without -march=native: valgrind cannot run AVX-512 instructions.
# The profile preset builds for AVX2, which the release build's search uses too; the portable
# preset has neither AVX2 nor popcnt, so its counts are of other code. Instructions, not time: the same in every run on a loaded machine.
set -euo pipefail
cd "$(dirname "$0")/../.."
(($# >= 1 && $# <= 2)) || { echo "usage: bench/peers/profile.sh BIN_DIR [WxH]" >&2; exit 2; }
bin=$1 size=${2-640x360}
[[ $size =~ ^([1-9][0-9]*)x([1-9][0-9]*)$ ]] || { echo "profile.sh: size must be WxH, not '$size'" >&2; exit 2; }
w=${BASH_REMATCH[1]} h=${BASH_REMATCH[2]}
[[ -x $bin/ch10 ]] || { echo "profile.sh: no chapter program $bin/ch10 (build the profile preset)" >&2; exit 2; }
command -v valgrind >/dev/null || { echo "profile.sh: valgrind is not installed" >&2; exit 2; }
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
python3 - "$out/mirrors.json" <<'PY'
import os, sys
sys.path.insert(0, "bench/peers")
from rtlab_scene import rtlab_scene
from scenes import rtiow
open(sys.argv[1], "w").write(rtlab_scene(rtiow(1, glass=False)))
PY
stats=$(valgrind --tool=callgrind --callgrind-out-file="$out/cg" "$bin/ch10" --scene "$out/mirrors.json" \
    --width "$w" --height "$h" --spp 1 --threads 1 --stats -o "$out/mirrors.png" 2>/dev/null)
rays=$(sed -E 's/.*"total":([0-9]+).*/\1/' <<<"$stats")
echo "rtiow-mirrors at ${w}x$h, 1 thread, callgrind; rays: $(sed -E 's/.*"rays":(\{[^}]*\}).*/\1/' <<<"$stats")"
echo
printf '%14s %9s %6s  %s\n' instructions "per ray" share function
callgrind_annotate --inclusive=no "$out/cg" 2>/dev/null | awk -v rays="$rays" '
    /PROGRAM TOTALS/ { gsub(",", "", $1); total = $1; next }
    total && /^ *[0-9,]+ .*[:(]/ && shown < 15 {
        n = $1; gsub(",", "", n)
        f = $0; sub(/^ *[0-9,]+ +(\([^)]*\) +)?/, "", f); sub(/ \[[^]]*\]$/, "", f)
        if (length(f) > 90) f = substr(f, 1, 87) "..."
        printf "%14d %9.1f %5.1f%%  %s\n", n, n / rays, 100 * n / total, f
        shown++
    }
    END { printf "%14d %9.1f %5.1f%%  %s\n", total, total / rays, 100, "the whole process" }'
