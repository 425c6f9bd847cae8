#!/usr/bin/env bash
# The statistical grade of the noisy chapters (book §14.6), measured:
#   1. false alarms: for every scene with a statistical reference, G groups of 8 correct
#      renders (the reference solution, seeds S, S+1, ...; none that the reference or the
#      tests use), each tested as a student's image is: how many groups fail; the smallest p
#      over all groups; its family p, 1 - (1 - p)^N for N pixel-channels, the alpha at which
#      that worst group would have failed; and how many groups have a family p below 0.1,
#      the false alarms at alpha = 10 %, where G groups say more than at 1 % (for a correct
#      sampler the family p is, by Šidák's inequality, at least as large as a uniform number);
#   2. planted bugs: every sampler bug the tests plant, rendered with the tests' seeds
#      (101-108): how many pixel-channels fail at the corrected level, and the smallest p.
# Render settings, seeds and tolerance are read from tools/settings.cmake, so the verdicts are
# the tests'. Arguments after -- go to rtlab-stat after the tolerance (they win), e.g.
# `-- --var-renders 0` for the z-test that takes the reference's variance as exact.
#
#   bench/false_alarms.sh [--build DIR] [--golden DIR] [--groups G] [--first-seed S] [--no-planted] [-- ARGS]
#
# DIR (default build/check) needs rtlab-stat, ch14-ch18 and planted_*: cmake --build --preset
# check --target rtlab-stat ch14 ch15 ch16 ch17 ch18 and the planted_ targets of tests/CMakeLists.txt.
# The book's tables (§14.6) are the default, 200 groups: 16,000 renders, about 5 minutes on
# 2 cores. ./lab bench false-alarms runs this in the release and the float build and writes
# the tables with bench/false_alarms_tables.py.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
build=build/check golden=tests/golden groups=200 first=20000 planted=1 extra=()
while (($#)); do
    case $1 in
    --build) build=$2 && shift 2 ;;
    --golden) golden=$2 && shift 2 ;;
    --groups) groups=$2 && shift 2 ;;
    --first-seed) first=$2 && shift 2 ;;
    --no-planted) planted=0 && shift ;;
    --) shift && extra=("$@") && break ;;
    *) echo "usage: bench/false_alarms.sh [--build DIR] [--golden DIR] [--groups G] [--first-seed S] [--no-planted] [-- ARGS]" >&2 && exit 2 ;;
    esac
done
setting() { cmake -DGET="$1" -P tools/settings.cmake; }
read -ra render_args <<<"$(setting RTLAB_STAT_ARGS)"
read -ra tolerance <<<"$(setting RTLAB_STAT_TOLERANCE)"
read -ra test_seeds <<<"$(setting RTLAB_STAT_SEEDS)"
read -ra noisy <<<"$(setting RTLAB_NOISY_CHAPTERS)"
stat=$build/bin/rtlab-stat
work=$(mktemp -d /tmp/rtlab-false-alarms.XXXXXX)
trap 'rm -rf "$work"' EXIT

# test PROGRAM CH SCENE SEED... [-- RENDER_ARGS]: prints "failed smallest_p tests pass"
test_renders() {
    local program=$1 ch=$2 scene=$3 images=() seed more=()
    shift 3
    local seeds=()
    while (($#)) && [[ $1 != -- ]]; do seeds+=("$1") && shift; done
    (($#)) && shift && more=("$@")
    for seed in "${seeds[@]}"; do
        images+=("$work/$scene-$seed.pfm")
        "$program" --scene "$scene" "${render_args[@]}" "${more[@]}" --seed "$seed" -o "${images[-1]}" >/dev/null
    done
    "$stat" test "$golden/ch$ch/$scene.mean.pfm" "$golden/ch$ch/$scene.var.pfm" "${images[@]}" \
        "${tolerance[@]}" "${extra[@]}" --json "$work/verdict.json" >/dev/null || (($? == 1))
    rm -f "${images[@]}"
    sed 's/[{}",:]/ /g' "$work/verdict.json" |
        awk '{for (i = 1; i < NF; i++) v[$i] = $(i + 1); print v["failed"], v["smallest_p"], v["tests"], v["pass"]}'
}

echo "rtlab-stat test ${tolerance[*]} ${extra[*]}; renders ${render_args[*]}; $groups groups of 8 from seed $first"
printf '%-16s %10s %12s %10s %16s\n' scene failing "smallest p" "family p" "family p < 0.1"
for ch in "${noisy[@]}"; do
    for mean in "$golden/ch$ch"/*.mean.pfm; do
        scene=$(basename "$mean" .mean.pfm)
        : >"$work/groups.txt"
        for ((g = 0; g < groups; g++)); do
            test_renders "$build/bin/ch$ch" "$ch" "$scene" $(seq $((first + 8 * g)) $((first + 8 * g + 7))) \
                >>"$work/groups.txt"
        done
        # The family p of a group: 1 - (1 - p)^N, written so that a tiny p keeps its digits.
        awk -v name="ch$ch $scene" -v groups="$groups" '
            function family(p, n) { return p < 1e-9 ? n * p : 1 - exp(n * log(1 - p)) }
            { fail += ($4 == "false"); if (NR == 1 || $2 < least) least = $2; n = $3
              below += (family($2, n) < 0.1) }
            END { printf "%-16s %3d of %-4d %12.3g %10.3g %9d of %-4d\n", name, fail, groups, least,
                  family(least, n), below, groups }' "$work/groups.txt"
        cat "$work/groups.txt" >>"$work/all.txt"
    done
done
awk '{ fail += ($4 == "false") }
    END { printf "%-16s %3d of %-4d (%.2f %%)\n", "every scene", fail, NR, 100 * fail / NR }' "$work/all.txt"

((planted)) || exit 0
echo
echo "planted bugs, seeds ${test_seeds[*]}"
printf '%-46s %12s %12s %8s\n' "bug (program, scene)" "failing" "smallest p" verdict
planted_row() {  # planted_row LABEL PROGRAM CH SCENE [RENDER_ARGS...]
    local label=$1 program=$2 ch=$3 scene=$4
    shift 4
    test_renders "$build/bin/$program" "$ch" "$scene" "${test_seeds[@]}" -- "$@" |
        awk -v name="$label" '{printf "%-46s %4d of %-4d %12.3g %8s\n", name, $1, $3, $2, $4 == "true" ? "pass" : "FAIL"}'
}
planted_row "box filter (ch14 --filter box, edges)" ch14 14 edges --filter box
planted_row "regular pattern (ch14 --pattern, checker)" ch14 14 checker --pattern regular
# Each planted/ file with the scene its test uses (rtlab_planted in tests/CMakeLists.txt).
sed -n 's/^ *rtlab_planted(\([a-z_]*\) \([0-9]*\) \([a-z]*\))$/\1 \2 \3/p' tests/CMakeLists.txt |
    while read -r name ch scene; do
        planted_row "$name (planted_$name, $scene)" "planted_$name" "$ch" "$scene"
    done
