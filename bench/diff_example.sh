#!/usr/bin/env bash
# Book §0.7's example of rtlab-diff, run for real (./lab bench counts): chapter 2's sphere at
# 16 samples per pixel against its 1-sample golden image, with the golden tolerance. The book
# says antialiasing alone is past that tolerance; a run where it is not fails here.
#
#   bench/diff_example.sh BIN_DIR OUT.md
set -euo pipefail
cd "$(dirname "$0")/.."
bin=${1:?usage: bench/diff_example.sh BIN_DIR OUT.md} out=${2:?usage: bench/diff_example.sh BIN_DIR OUT.md}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
render=(build/release/bin/ch02 --scene sphere --width 160 --height 120 --seed 1 --spp 16 -o /tmp/s16.png)
diff=(build/release/bin/rtlab-diff tests/golden/ch02/sphere.png /tmp/s16.png
    --radius 1 --threshold 8 --max-over 0.5 --max-rmse 2 --heatmap /tmp/h.png)
"$bin/ch02" "${render[@]:1:10}" -o "$tmp/s16.png" >/dev/null
code=0
result=$("$bin/rtlab-diff" tests/golden/ch02/sphere.png "$tmp/s16.png" "${diff[@]:3:8}" --heatmap "$tmp/h.png" 2>&1) || code=$?
if ((code != 1)); then
    echo "diff_example: expected the 16 spp render past the golden tolerance (exit 1), got exit $code:" >&2
    echo "$result" >&2
    exit 1
fi
{
    echo '```'
    echo "\$ ${render[*]}"
    echo "\$ ${diff[*]:0:3} \\"
    echo "      ${diff[*]:3}"
    echo "$result"
    echo '```'
} >"$out"
cat "$out"
