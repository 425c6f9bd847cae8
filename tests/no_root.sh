#!/usr/bin/env bash
# No root once installed: the lab as an ordinary user on a machine whose packages are there
# (./lab test runs this after making sure of its own). In a copy of the lab's files:
#  1. With dpkg's database empty for it (DPKG_ADMINDIR: dpkg-query finds nothing installed),
#     ./lab run, ./lab test and ./lab grade each exit 2 with one line `sudo apt-get install ...`
#     naming the packages they need, call neither sudo nor apt-get, and change no file.
#  2. ./lab deps test (everything there: ./lab test made sure) exits 0 and calls neither.
#  3. ./lab grade 01 --solved 01 builds chapter 1's programs and grades them: every test passes.
# Run as root (./lab test in CI), all of it runs as the throwaway user nobody (setpriv), with a
# home of its own in a scratch folder that is removed afterwards; run as anyone else, as that
# user (then ./lab test itself has already built and graded everything without root).
#   tests/no_root.sh LAB_DIR
set -euo pipefail
lab=$(cd "${1:?usage: tests/no_root.sh LAB_DIR}" && pwd)
scratch=$(mktemp -d /tmp/rtlab-no-root.XXXXXX)
trap 'rm -rf "$scratch"' EXIT
chmod 755 "$scratch"
copy=$scratch/lab
mkdir -p "$copy" "$scratch/home" "$scratch/empty-dpkg" "$scratch/bin"
git -C "$lab" ls-files -z | (cd "$lab" && tar --null -T - -cf -) | tar -C "$copy" -xf -
: >"$scratch/empty-dpkg/status"
# sudo and apt-get that only say they were called.
for tool in sudo apt-get; do
    printf '#!/bin/sh\necho "%s $*" >>%s/called\nexit 1\n' "$tool" "$scratch" >"$scratch/bin/$tool"
    chmod 755 "$scratch/bin/$tool"
done
if ((EUID == 0)); then
    chown -R nobody: "$copy" "$scratch/home"
    chmod 1777 "$scratch"  # for the fake tools' record, written as nobody
    as_user=(setpriv --reuid=nobody --regid=nogroup --clear-groups)
    who="the user nobody"
else
    as_user=()
    who="$(id -un) (not root)"
fi
user_env=(env -i HOME="$scratch/home" LANG=C.UTF-8 PATH="$scratch/bin:/usr/local/bin:/usr/bin:/bin")
# The compiler cache ./lab test has just filled, read-only (CCACHE_READONLY: nothing is stored),
# through a copy the user can read (root's home is closed to it): the grade below then costs a
# link, not a whole library compiled again. What this test checks (no root needed to configure,
# build, link, run and grade) is unchanged: a miss compiles as that user, as without a cache.
if ((EUID == 0)) && command -v ccache >/dev/null && cache=$(ccache -k cache_dir 2>/dev/null) && [[ -d $cache ]]; then
    cp -al "$cache" "$scratch/ccache" 2>/dev/null || cp -a "$cache" "$scratch/ccache"
    chmod -R a+rX "$scratch/ccache"
    user_env+=(CCACHE_DIR="$scratch/ccache" CCACHE_READONLY=1 CCACHE_TEMPDIR="$scratch/home/ccache-tmp")
fi
failures=0
fail() { echo "no_root: FAILED: $*" >&2; failures=$((failures + 1)); }
listing() { find "$copy" -printf '%P %s %T@\n' | sort; }

# 1. Nothing installed: one line that says what to install, and nothing done.
before=$(listing)
for command in run test grade; do
    set +e
    out=$("${as_user[@]}" "${user_env[@]}" DPKG_ADMINDIR="$scratch/empty-dpkg" "$copy/lab" $command 2>&1 >/dev/null)
    rc=$?
    set -e
    lines=$(grep -c '^sudo apt-get install ' <<<"$out" || true)
    ((rc == 2)) || fail "./lab $command with no package installed exited $rc, not 2: $out"
    ((lines == 1)) || fail "./lab $command with no package installed printed $lines 'sudo apt-get install' lines, not 1: $out"
    for p in cmake g++ libtbb-dev $( [[ $command == run ]] && echo pandoc) $( [[ $command == test ]] && echo clang git); do
        grep -q "^sudo apt-get install .* $p\( \|$\)" <<<"$out" || fail "./lab $command's install line does not name $p: $out"
    done
done
[[ $(listing) == "$before" ]] || fail "./lab with packages missing changed files of the lab: $(diff <(echo "$before") <(listing) | head -5)"
[[ ! -e $scratch/called ]] || fail "./lab with packages missing called: $(cat "$scratch/called")"

# 2. Everything installed: nothing to do.
"${as_user[@]}" "${user_env[@]}" "$copy/lab" deps test || fail "./lab deps test exited $? with its packages installed"
[[ ! -e $scratch/called ]] || fail "./lab deps test with its packages installed called: $(cat "$scratch/called")"

# 3. A build and a grade, as that user.
if ((EUID == 0)); then
    if ! "${as_user[@]}" "${user_env[@]}" "$copy/lab" grade 01 --solved 01 --expect all >"$scratch/grade.txt" 2>&1; then
        fail "./lab grade 01 --solved 01 as $who: $(tail -20 "$scratch/grade.txt")"
    fi
    [[ ! -e $scratch/called ]] || fail "./lab grade called: $(cat "$scratch/called")"
fi
if ((failures)); then
    exit 1
fi
echo "no_root: as $who: ./lab run, test and grade refuse with one install line and change nothing when packages are missing; ./lab deps test has nothing to do$( ((EUID == 0)) && echo "; ./lab grade 01 built and passed")"
