#!/usr/bin/env bash
# test_shipped_scenes.sh: every shipped scene (data/scenes/*.ini) through `gallop simulate` with the
# reduced model (the default) over a short run: exit 0 and "valid": true in summary.json, a finite
# residual_max at most model.residual_tolerance's default, and on a scene without wind (a still
# span: nothing drives it, its motion is round-off) no growth of the basis. Before the self-check's
# scale had a physical floor (src/reduced/rom_check.c), drake_300m.ini exited 1 at t = 8 s after
# growing its basis 8 times on round-off. No scene is skipped: the reduced model takes them all.
# Run from the repository root (scenes name their conductor from data/conductors.csv).
set -u
: "${GALLOP:?GALLOP must hold the path of the gallop binary}"
. "$(dirname "$0")/lib.sh"
scratch shipped

# json KEY FILE: the first value of "KEY": in FILE
json() { grep -o "\"$1\": [^,}]*" "$2" | head -n 1 | sed 's/.*: //'; }

DURATION=20 # s: past the 8 s where drake_300m failed, a few seconds of the whole suite
n=0
for scene in data/scenes/*.ini; do
    name=$(basename "$scene" .ini)
    n=$((n + 1))
    out=$tmp/$name
    timeout 120 "$GALLOP" simulate "$scene" --set simulation.duration=$DURATION -o "$out" \
        >"$out.out" 2>"$out.err"
    rc=$?
    if [ $rc -ne 0 ]; then
        bad "$name: exit $rc: $(tail -n 1 "$out.err" | cut -c1-200)"
        continue
    fi
    s=$out/summary.json
    if [ ! -s "$s" ]; then bad "$name: no summary.json"; continue; fi
    ok "$name: exit 0"
    if [ "$(json valid "$s")" = "true" ]; then ok "$name: valid"; else bad "$name: valid is $(json valid "$s")"; fi
    r=$(json residual_max "$s")
    if awk -v r="$r" 'BEGIN{exit !(r == r + 0 && r >= 0 && r <= 0.1)}'; then
        ok "$name: residual_max $r within the default tolerance 0.1"
    else
        bad "$name: residual_max '$r' is not a finite number within 0.1"
    fi
    if ! grep -q '^\[wind\]' "$scene"; then # a still span
        g=$(grep -o '"basis_growths": \[[^]]*\]' "$s")
        if [ "$g" = '"basis_growths": []' ]; then ok "$name (still): the basis did not grow"
        else bad "$name (still): the basis grew on round-off: $(echo "$g" | cut -c1-200)"; fi
    fi
done
if [ $n -ge 6 ]; then ok "$n shipped scenes run"; else bad "only $n shipped scenes found (run from the repository root)"; fi

finish
