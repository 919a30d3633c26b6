#!/usr/bin/env bash
# test_cli_help.sh: the command line's documentation: `gallop --help` lists every command,
# `gallop COMMAND --help` exits 0 with the command's usage and every option of its table,
# `gallop --version`, and the man page doc/gallop.1 renders without warnings and names every
# command and option; bad usage exits 2 with the synopsis.
set -u
: "${GALLOP:?GALLOP must hold the path of the gallop binary}"
. "$(dirname "$0")/lib.sh"
scratch help

"$GALLOP" --help > "$tmp/help" 2>&1 && ok "gallop --help exits 0" || bad "gallop --help: exit $?"
commands="modes simulate compare stability wind accuracy spectrum sweep check version"
for c in $commands; do
  grep -q "^  gallop $c" "$tmp/help" || bad "gallop --help does not list $c"
done
ok "gallop --help lists the commands"
"$GALLOP" --version | grep -Eq '^gallop [0-9]+\.[0-9]+' && ok "gallop --version: $("$GALLOP" --version)" \
  || bad "gallop --version"
man_txt=$tmp/man.txt
if command -v groff >/dev/null; then
  groff -man -Tascii -ww doc/gallop.1 2> "$tmp/groff.err" | col -bx > "$man_txt"
  [ -s "$man_txt" ] && [ ! -s "$tmp/groff.err" ] && ok "doc/gallop.1 renders without warnings" \
    || bad "doc/gallop.1: $(head -3 "$tmp/groff.err")"
else
  sed 's/\\-/-/g; s/\\f[BIR]//g' doc/gallop.1 > "$man_txt"
fi
for c in $commands; do
  "$GALLOP" "$c" --help > "$tmp/h_$c" 2>&1; rc=$?
  [ $rc -eq 0 ] && grep -q "^usage: gallop $c" "$tmp/h_$c" || { bad "gallop $c --help: exit $rc"; continue; }
  # every option of the usage (the --name words) is in the man page
  missing=""
  for o in $(grep -o -- '--[a-z][a-z-]*' "$tmp/h_$c" | sort -u); do
    grep -q -- "$o" "$man_txt" || missing="$missing $o"
  done
  grep -q "$c" "$man_txt" || missing="$missing (the command)"
  [ -z "$missing" ] && ok "gallop $c --help; the man page has its options" || bad "man page lacks for $c:$missing"
done
# option parsing: --name=value, options after the operand, -- ends the options
if "$GALLOP" check --set=span.length=310 data/scenes/drake_300m.ini | grep -q '^length = 310'; then
  ok "--set=VALUE form"
else bad "--set=VALUE form"; fi
# bad usage: exit 2 with the synopsis
for args in "modes" "modes a.ini b.ini" "modes --frobnicate x.ini" "simulate x.ini --model" "version extra" "nosuch"; do
  "$GALLOP" $args > /dev/null 2> "$tmp/err"; rc=$?
  [ $rc -eq 2 ] && grep -q 'usage' "$tmp/err" && ok "'gallop $args': exit 2 with the usage" \
    || bad "'gallop $args': exit $rc: $(head -2 "$tmp/err")"
done
finish
