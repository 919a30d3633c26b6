#!/usr/bin/env bash
# test_cli_cigre.sh: the CIGRE TB 322 tension outputs of `gallop simulate` in summary.json: with a
# conductor whose rated strength is known (Drake) support_tensions holds rated_strength_n (the
# table's) and max_over_rated_strength = max_n / rated_strength_n; with one whose rated strength
# is unknown (Grosbeak) both keys are absent (never a NaN); a --set rated_strength is used; a bundle's
# strength is its sub-conductors'.
set -u
: "${GALLOP:?GALLOP must hold the path of the gallop binary}"
. "$(dirname "$0")/lib.sh"
scratch cli_cigre
cp data/scenes/iced_gallop.ini "$tmp/iced.ini"
short=(--model reduced --set ice.aero_table="$PWD/data/aero/iced_d_shape.csv" --set model.elements=30
       --set simulation.duration=20)

# run NAME SETTINGS...: simulate into $tmp/NAME
run() {
    local name=$1; shift
    "$GALLOP" simulate "$tmp/iced.ini" "${short[@]}" "$@" -o "$tmp/$name" >"$tmp/$name.out" 2>&1 \
        || { bad "$name: simulate exit $?: $(tail -n 2 "$tmp/$name.out")"; return 1; }
}

if run drake; then
    js=$tmp/drake/summary.json
    rts=$(jq -r '.support_tensions.rated_strength_n // "absent"' "$js")
    # Drake: 31,200 lb (GO 95 Table 23) = 138780 N in the table
    [ "$rts" = 138780 ] && ok "Drake: rated_strength_n = 138780 N" || bad "Drake: rated_strength_n = $rts"
    if jq -e '.support_tensions | (.max_over_rated_strength - .max_n / .rated_strength_n | fabs) < 1e-9 * .max_over_rated_strength
              and .max_over_rated_strength > 0' "$js" >/dev/null; then
        ok "max_over_rated_strength = max_n / rated_strength_n"
    else
        bad "max_over_rated_strength: $(jq -c .support_tensions "$js")"
    fi
fi
if run grosbeak --set conductor.name=Grosbeak; then
    js=$tmp/grosbeak/summary.json
    jq -e '.support_tensions | has("max_n") and (has("rated_strength_n") | not) and (has("max_over_rated_strength") | not)' \
        "$js" >/dev/null && ok "Grosbeak (no rated strength): ratio absent, max_n present" \
        || bad "Grosbeak: $(jq -c .support_tensions "$js")"
fi
if run given --set conductor.rated_strength=100000; then
    jq -e '.support_tensions.rated_strength_n == 100000' "$tmp/given/summary.json" >/dev/null \
        && ok "a given rated_strength is the one used" || bad "given: $(jq -c .support_tensions "$tmp/given/summary.json")"
fi
# a quad bundle: its tensions are the bundle's, set against four sub-conductors' strength
if run quad --set bundle.subconductors=4 --set bundle.separation=0.457; then
    jq -e '.support_tensions.rated_strength_n == 4 * 138780 and .bundle.subconductors == 4' "$tmp/quad/summary.json" \
        >/dev/null && ok "quad bundle: rated_strength_n = 4 x 138780 N" \
        || bad "quad: $(jq -c '[.support_tensions, .bundle]' "$tmp/quad/summary.json")"
fi
finish
