#!/usr/bin/env bash
# make mutate: applies each mutant of tests/mutate/mutants.txt to a copy of the sources, builds it,
# runs the whole suite (stopping at the first failing program) and counts the mutants the suite
# kills. A mutant is one exact text replacement in one file (the text must occur exactly once).
# Prints a line per mutant, the kill rate, and the survivors with the reason each is harmless
# (their `harmless:` line) — a survivor without one is a missing test.
# Usage: bash tests/mutate/run.sh [MUTANT_ID ...]   (no ids: all of them)
set -u
top=$(cd "$(dirname "$0")/../.." && pwd)
list="$top/tests/mutate/mutants.txt"
work=$(mktemp -d /tmp/gallop_mutate_XXXXXX)
trap 'rm -rf "$work"' EXIT
# a copy of the tracked sources as they are in the working tree
(cd "$top" && git ls-files -z | xargs -0 -I{} cp --parents {} "$work/")
cd "$work" || exit 2
echo "mutate: building the unmutated copy in $work"
if ! make -j2 build/gallop >/dev/null 2>&1 || ! FAIL_FAST=1 make -j2 check >"$work/base.log" 2>&1; then
    echo "mutate: the unmutated suite fails; fix that first (log: $work/base.log)" >&2
    tail -n 20 "$work/base.log" >&2
    exit 2
fi

# parse the list into records: id, file, from, to, harmless
records=$(awk '
    function flush() { if (id != "") printf "%s\x1f%s\x1f%s\x1f%s\x1f%s\x1e", id, file, from, to, harmless; id=file=from=to=harmless="" }
    /^mutant:/   { flush(); sub(/^mutant: */, ""); id=$0; next }
    /^file:/     { sub(/^file: */, ""); file=$0; next }
    /^from:/     { sub(/^from: /, ""); from=$0; next }
    /^to:/       { sub(/^to: ?/, ""); to=$0; next }
    /^harmless:/ { sub(/^harmless: */, ""); harmless=$0; next }
    END { flush() }' "$list")

killed=0; survived=0; invalid=0; total=0; surv_list=""
t0=$SECONDS
while IFS=$'\x1f' read -r -d $'\x1e' id file from to harmless; do
    if [ $# -gt 0 ]; then
        want=0; for w in "$@"; do [ "$w" = "$id" ] && want=1; done
        [ $want = 1 ] || continue
    fi
    total=$((total + 1))
    n=$(FROM="$from" perl -0ne '$c = () = /\Q$ENV{FROM}\E/g; print $c' "$file" 2>/dev/null)
    if [ "$n" != 1 ]; then
        echo "  INVALID $id: '$from' occurs ${n:-0} times in $file (must be once)"
        invalid=$((invalid + 1)); continue
    fi
    cp "$file" "$work/orig"
    FROM="$from" TO="$to" perl -0pi -e 's/\Q$ENV{FROM}\E/$ENV{TO}/' "$file"
    if ! make -j2 build/gallop >"$work/build.log" 2>&1 </dev/null; then
        echo "  INVALID $id: does not build"
        invalid=$((invalid + 1))
    elif FAIL_FAST=1 timeout 900 make -j2 check >"$work/check.log" 2>&1 </dev/null; then
        survived=$((survived + 1))
        echo "  SURVIVED $id ($file)${harmless:+: harmless: $harmless}"
        surv_list="$surv_list\n  $id: ${harmless:-NO REASON GIVEN: a missing test}"
    else
        killed=$((killed + 1))
        by=$(grep -m1 -E '^  FAIL' "$work/check.log" | sed 's/^  FAIL //' | cut -c1-70)
        echo "  killed   $id by ${by:-a failing program}"
    fi
    cp "$work/orig" "$file"
    touch "$file"
done <<<"$records"
valid=$((killed + survived))
rate=$(awk -v k=$killed -v v=$valid 'BEGIN{printf "%.1f", v ? 100 * k / v : 0}')
echo "mutate: $killed of $valid mutants killed ($rate%), $invalid invalid, $((SECONDS - t0)) s"
[ -n "$surv_list" ] && printf "survivors:$surv_list\n"
[ $invalid -eq 0 ]
