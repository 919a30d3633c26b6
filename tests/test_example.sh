#!/usr/bin/env bash
# test_example.sh: the README's library example is examples/first_frequencies.c verbatim (the
# fenced block after the "example:" marker), `make check` built it (GALLOP_EXAMPLES), and it
# prints the frequencies `gallop modes` finds (the first horizontal and vertical modes).
set -u
: "${GALLOP:?GALLOP must hold the path of the gallop binary}"
. "$(dirname "$0")/lib.sh"
scratch example

awk '/^<!-- example: examples\/first_frequencies.c -->/ { on = 1; next }
     on && /^```c/ { inb = 1; next } inb && /^```/ { exit } inb { print }' README.md > "$tmp/readme.c"
if [ -s "$tmp/readme.c" ] && cmp -s "$tmp/readme.c" examples/first_frequencies.c; then
  ok "README's example is examples/first_frequencies.c verbatim ($(wc -l < "$tmp/readme.c") lines)"
else
  bad "README's example differs from examples/first_frequencies.c: $(diff "$tmp/readme.c" examples/first_frequencies.c | head -3)"
fi
ex=${GALLOP_EXAMPLES:-build/examples}/first_frequencies
if [ -x "$ex" ] && "$ex" data/scenes/drake_300m.ini > "$tmp/out" 2> "$tmp/err"; then
  ok "the example runs: $(head -1 "$tmp/out")"
else
  bad "the example ($ex): exit $?: $(cat "$tmp/err" 2>/dev/null)"
fi
"$GALLOP" modes data/scenes/drake_300m.ini -o "$tmp/modes" > /dev/null
for fam in horizontal vertical; do
  a=$(awk -v f="$fam" '$1 == f { print $2; exit }' "$tmp/out")
  b=$(awk -F, -v f="$fam" '$2 == f { print $4; exit }' "$tmp/modes/modes.csv")
  awk -v a="$a" -v b="$b" 'BEGIN { d = a - b; exit !(a > 0 && (d < 0 ? -d : d) < 1e-6 * b) }' \
    && ok "first $fam frequency $a Hz = gallop modes $b Hz" || bad "first $fam: example $a Hz, gallop modes $b Hz"
done
finish
