#!/usr/bin/env bash
# test_bundle_cli.sh: an explicit bundle ([bundle] model = explicit) through the real binary:
# `gallop modes` writes the single rod's files with the sub-conductor named (equilibrium.csv and
# shapes.csv column sub, modes.csv share_subspan); simulate, compare and stability refuse it with
# exit 2, naming the file, the line and [bundle] model, and saying equivalent is what runs.
set -u
: "${GALLOP:?GALLOP must hold the path of the gallop binary}"
pass=0; fail=0
ok()  { pass=$((pass + 1)); echo "  ok   $1"; }
bad() { fail=$((fail + 1)); echo "  FAIL $1"; }
tmp=$(mktemp -d /tmp/gallop_bundle_cli_XXXXXX)
trap 'rm -rf "$tmp"' EXIT

sed 's/^model = equivalent/model = explicit/' data/scenes/quad_bundle_gallop.ini > "$tmp/quad.ini"
sed -i 's#\.\./aero/#'"$PWD"'/data/aero/#' "$tmp/quad.ini"
line=$(grep -n '^model = explicit' "$tmp/quad.ini" | cut -d: -f1)

if "$GALLOP" modes "$tmp/quad.ini" -o "$tmp/modes" > "$tmp/modes.txt" 2>&1; then ok "modes runs"; else bad "modes runs: $(cat "$tmp/modes.txt")"; fi
grep -q 'explicit bundle of 4 sub-conductors, 6 spacers' "$tmp/modes.txt" && ok "table names the bundle" || bad "table names the bundle"
head -1 "$tmp/modes/modes.csv" 2>/dev/null | grep -q 'share_subspan' && ok "modes.csv share_subspan" || bad "modes.csv share_subspan"
head -1 "$tmp/modes/shapes.csv" 2>/dev/null | grep -q '^mode,family,frequency_hz,sub,node' && ok "shapes.csv sub" || bad "shapes.csv sub"
subs=$(tail -n +2 "$tmp/modes/equilibrium.csv" 2>/dev/null | cut -d, -f1 | sort -u | tr '\n' ' ')
[ "$subs" = "1 2 3 4 " ] && ok "equilibrium.csv: 4 sub-conductors" || bad "equilibrium.csv: sub-conductors '$subs'"
grep -q '"model": "explicit"' "$tmp/modes/summary.json" 2>/dev/null && ok "summary.json bundle" || bad "summary.json bundle"

for cmd in simulate compare stability; do
    "$GALLOP" $cmd "$tmp/quad.ini" -o "$tmp/$cmd" > "$tmp/$cmd.txt" 2>&1
    rc=$?
    if [ $rc -eq 2 ] && grep -q "quad.ini:$line: \[bundle\] model = explicit" "$tmp/$cmd.txt" &&
       grep -q 'allowed: model = equivalent' "$tmp/$cmd.txt" && [ ! -e "$tmp/$cmd" ]; then
        ok "$cmd refuses the explicit model (exit 2, line $line)"
    else
        bad "$cmd: exit $rc: $(cat "$tmp/$cmd.txt")"
    fi
done
"$GALLOP" simulate data/scenes/quad_bundle_gallop.ini --set bundle.model=explicit -o "$tmp/s2" > "$tmp/s2.txt" 2>&1
rc=$?
[ $rc -eq 2 ] && grep -q -- '--set: \[bundle\] model = explicit' "$tmp/s2.txt" && ok "--set explicit refused" || bad "--set: exit $rc: $(cat "$tmp/s2.txt")"

echo "#summary $pass $fail"
[ "$fail" -eq 0 ]
