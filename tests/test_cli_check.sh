#!/usr/bin/env bash
# test_cli_check.sh: `gallop check` on the shipped demo scene (exit 0, the resolved scene reads
# back), on a bad scene (exit 2, FILE:LINE on stderr) and on bad arguments (exit 2).
set -u
: "${GALLOP:?GALLOP must hold the path of the gallop binary}"
. "$(dirname "$0")/lib.sh"
scratch cli_check

# the shipped scene
if "$GALLOP" check data/scenes/drake_300m.ini >"$tmp/out.ini" 2>"$tmp/err"; then
  ok "check drake_300m.ini exits 0"
else
  bad "check drake_300m.ini: exit $?: $(cat "$tmp/err")"
fi
if grep -q '^horizontal_tension = 28000 ' "$tmp/out.ini" && grep -q '^name = Drake$' "$tmp/out.ini"; then
  ok "check prints the resolved scene"
else
  bad "check output lacks the tension or the conductor name"
fi
# what check prints, check reads back and prints the same way
cp "$tmp/out.ini" "$tmp/drake_300m.ini"
if GALLOP_DATA=data "$GALLOP" check "$tmp/drake_300m.ini" >"$tmp/out2.ini" 2>"$tmp/err" &&
   diff <(grep -v '^#' "$tmp/out.ini") <(grep -v '^#' "$tmp/out2.ini") >/dev/null; then
  ok "the printed scene reads back the same"
else
  bad "round trip: $(cat "$tmp/err")"
fi
# --set
if "$GALLOP" check data/scenes/drake_300m.ini --set span.length=250 --set model.elements=50 \
     2>/dev/null | grep -q '^elements = 50 '; then
  ok "--set overrides"
else
  bad "--set overrides"
fi

# a bad scene: exit 2, stderr names file and line
printf '[span]\nlength = 300\nhorizontal_tension = -5\n' >"$tmp/bad.ini"
"$GALLOP" check "$tmp/bad.ini" >"$tmp/out" 2>"$tmp/err"; rc=$?
if [ "$rc" -eq 2 ] && grep -q "bad.ini:3: .*horizontal_tension" "$tmp/err" && [ ! -s "$tmp/out" ]; then
  ok "bad scene: exit 2, message names line 3"
else
  bad "bad scene: exit $rc, stderr: $(cat "$tmp/err")"
fi

# bad arguments
for args in "" "--bogus data/scenes/drake_300m.ini" "data/scenes/drake_300m.ini --set" \
            "data/scenes/drake_300m.ini --set span.nokey=1" "data/scenes/drake_300m.ini extra.ini" \
            "/nonexistent.ini"; do
  # shellcheck disable=SC2086
  "$GALLOP" check $args >/dev/null 2>"$tmp/err"; rc=$?
  if [ "$rc" -eq 2 ] && [ -s "$tmp/err" ]; then ok "check $args: exit 2"; else bad "check $args: exit $rc"; fi
done

finish
