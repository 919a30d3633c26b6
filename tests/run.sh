#!/usr/bin/env bash
# Runs every test program given on the command line (and the shell tests), adds up the
# "#summary P F" lines and ends with "N passed, N failed"; exits non-zero on any failure.
# FAIL_FAST=1 stops at the first failing program (make mutate).
set -u
passed=0; failed=0
for t in "$@"; do
  name=$(basename "$t")
  echo "== $name"
  t0=$SECONDS
  case "$t" in
    *.sh) out=$(bash "$t" 2>&1); rc=$? ;;
    *)    out=$("$t" 2>&1); rc=$? ;;
  esac
  printf '%s\n' "$out" | grep -v '^#summary'
  sum=$(printf '%s\n' "$out" | grep '^#summary' | tail -n 1)
  if [ -n "$sum" ]; then
    read -r _ p f <<<"$sum"
    passed=$((passed + p)); failed=$((failed + f))
    if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then
      echo "  FAIL $name exited with status $rc"; failed=$((failed + 1))
    fi
  else
    echo "  FAIL $name: no summary (exit status $rc, crashed?)"; failed=$((failed + 1))
  fi
  echo "  [$name: $((SECONDS - t0)) s]"
  # FAIL_FAST=1 (make mutate): stop at the first failing program
  if [ -n "${FAIL_FAST:-}" ] && [ "$failed" -gt 0 ]; then break; fi
done
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
