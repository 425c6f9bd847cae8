#!/usr/bin/env bash
# Instructions per ray on each side of the Embree comparison (book §C.1): bench_embree
# --instructions casts each kind of ray (primary; shadow rays something blocks; shadow
# rays nothing blocks) N times on one thread, each side alone, and callgrind counts only
# those casts. Unlike times, the counts are the same in every run, on a loaded machine too.
#
#   bench/embree_instructions.sh BIN N [bench_embree options] [MESH.obj ...]
#   e.g. bench/embree_instructions.sh build/profile/bin/bench_embree 1 --no-procedural BUNNY.obj
#
# Debian 12's valgrind (3.19) cannot run AVX-512 instructions, which the release preset's
# -march=native emits on a processor that has them; build BIN with the profile preset
# instead (release for AVX2: the counts are then those of the AVX2 code):
#   cmake --preset profile && cmake --build build/profile --target bench_embree
set -euo pipefail
(($# >= 2)) || { echo "usage: bench/embree_instructions.sh BIN N [bench_embree options] [MESH.obj ...]" >&2; exit 2; }
bin=$1 n=$2
shift 2
[[ $n =~ ^[1-9][0-9]*$ ]] || { echo "bench/embree_instructions.sh: N must be a whole number from 1, not '$n'" >&2; exit 2; }
command -v valgrind >/dev/null || { echo "bench/embree_instructions.sh: needs valgrind" >&2; exit 2; }
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
# --instr-atstart=no: the builds and the agreement checks run uninstrumented (and faster).
if ! valgrind --tool=callgrind --instr-atstart=no --callgrind-out-file="$out/cg" "$bin" --instructions "$n" "$@" \
    >"$out/stdout" 2>"$out/valgrind"; then
    if grep -q "unhandled instruction" "$out/valgrind"; then
        echo "bench/embree_instructions.sh: valgrind cannot run $bin (AVX-512?): build it for AVX2, see the header" >&2
    else
        echo "bench/embree_instructions.sh: $bin failed under valgrind:" >&2
        tail -n 5 "$out/valgrind" >&2
    fi
    exit 1
fi
python3 - "$out"/cg.* <<'PY'
import re, sys
rows = {}  # (input, kind) -> {side: (instructions, rays)}
order = []
for path in sys.argv[1:]:
    desc = total = None
    with open(path) as f:
        for line in f:
            if line.startswith("desc: Trigger: Client Request: "):
                desc = line.split(": ", 3)[3].strip()
            elif line.startswith(("totals:", "summary:")):
                total = int(line.split()[1])
    m = desc and re.match(r"^(.*): (.*), (lab|Embree), (\d+) x (\d+) rays$", desc)
    if not m or total is None:
        continue
    key = (m.group(1), m.group(2))
    if key not in rows:
        order.append(key)
    rows.setdefault(key, {})[m.group(3)] = total / (int(m.group(4)) * int(m.group(5)))
print(f"instructions per ray (callgrind), one thread")
print(f"  {'input':22} {'rays':18} {'lab':>9} {'Embree':>9} {'Embree/lab':>11}")
for key in sorted(order, key=order.index):
    sides = rows[key]
    lab, emb = sides.get("lab"), sides.get("Embree")
    if lab is None or emb is None:
        continue
    print(f"  {key[0]:22} {key[1]:18} {lab:9.0f} {emb:9.0f} {emb / lab:11.2f}")
PY
