#!/usr/bin/env bash
# The loop a student lives in, timed the way a student meets it (book §B.6):
#   1. ./lab run on a fresh clone, with an empty compiler cache
#   2. ./lab run again, nothing changed
#   3. ./lab grade, every chapter, after a one-line change inside an exercise body (8.1)
#   4. ./lab grade 08 after another one-line change there
#   5. ./lab grade --solved "01;02;03" (a different set of chapters from solutions/)
#   6. with --with-test: ./lab test on a fresh clone, with an empty compiler cache and again
#      with the cache the first one filled (about half an hour more)
# The student of 3-5 has written every exercise (the reference bodies, copied in), so every
# chapter renders all of its images: the slowest case. The edits keep the answers right.
# The last lines are the table: "LABEL  SECONDS s  TARGET" (./lab bench fast-loop makes book
# §B.6's table of them, bench/fast_loop_table.py).
#
#   bench/fast_loop.sh [--with-test] [WORK_DIR]   (default: a new temporary folder; about 5 minutes)
#
# Timings belong here, not in tests: the machines are shared, so repeat a row that looks off.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
with_test=0
[[ ${1-} == --with-test ]] && { with_test=1; shift; }
work=${1:-$(mktemp -d /tmp/rtlab-fast-loop.XXXXXX)}
rm -rf "$work/lab" "$work/ccache"
mkdir -p "$work"
git clone -q "$root" "$work/lab"
cd "$work/lab"
export CCACHE_DIR="$work/ccache"  # empty: a first run compiles everything (when ccache is installed)
rows=() phases=()
timed() {  # timed LABEL TARGET COMMAND...
    local label=$1 target=$2 start end
    shift 2
    start=$(date +%s.%N)
    "$@" >"$work/last.log" 2>&1 || { cat "$work/last.log"; echo "fast_loop: '$*' failed" >&2; exit 1; }
    end=$(date +%s.%N)
    rows+=("$(printf '%-58s %8.1f s   %s' "$label" "$(awk "BEGIN{print $end - $start}")" "$target")")
    echo "${rows[-1]}"
}
edit_8_1() {  # edit_8_1 VALUE: a line inside exercise 8.1's body that changes the code, not the answer
    sed -i "/@exercise 8\.1 /a\\    if (n_from == Real($1)) return false;  // an edit (indices of refraction are positive)" \
        exercises/ch08_refraction.cpp
}

echo "fast loop, $(nproc) cores, $(sed -n 's/^model name\s*: //p' /proc/cpuinfo | head -1), in $work"
timed "./lab run, fresh clone, empty compiler cache" "<= 300 s" ./lab run
timed "./lab run again, nothing changed" "<= 15 s" ./lab run

python3 - <<'PY'
# The student writes every exercise: the reference bodies, put between @exercise and @end.
import glob, os, re
for solution in sorted(glob.glob("solutions/ch*.cpp")):
    exercise = "exercises/" + os.path.basename(solution)
    sol, ex = open(solution).read(), open(exercise).read()
    for m in re.finditer(r"// @exercise (\S+) .*?\n(.*?)\n\s*// @end", sol, re.S):
        ex = re.sub(r"(// @exercise " + re.escape(m.group(1)) + r" .*?\n).*?(\n\s*// @end)",
                    lambda e: e.group(1) + m.group(2) + e.group(2), ex, count=1, flags=re.S)
    open(exercise, "w").write(ex)
PY
timed "./lab grade, the first time (builds the exercises track)" "-" ./lab grade --solved "" --expect all
edit_8_1 -1
timed "./lab grade after a one-line edit in 8.1, all chapters" "<= 20 s" ./lab grade --expect all
edit_8_1 -2
timed "./lab grade 08 after another one-line edit in 8.1" "<= 8 s" ./lab grade 08 --expect all
timed "./lab grade --solved \"01;02;03\" (was none): every chapter relinked and graded" "<= 60 s" ./lab grade --solved "01;02;03" --expect all

if ((with_test)); then
    export CCACHE_DIR="$work/ccache-test"
    for cache in empty warm; do
        cd "$work"
        rm -rf "$work/test" && git clone -q "$root" "$work/test" && cd "$work/test"
        [[ $cache == empty ]] && rm -rf "$CCACHE_DIR"
        timed "./lab test, fresh clone, $cache compiler cache" "$([[ $cache == empty ]] && echo "<= 25 min" || echo "<= 12 min")" ./lab test
        # Where the time went: ./lab test stamps each phase with the time since it began.
        phases+=("$(sed -nE "s/^== (.*)  \(([0-9]+)m([0-9]+)s\)$/phase $cache \2 \3 \1/p" "$work/last.log")")
    done
fi
echo
printf '%s\n' "${rows[@]}"
if ((${#phases[@]})); then printf '%s\n' "${phases[@]}"; fi
