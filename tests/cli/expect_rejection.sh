#!/bin/sh
# Runs a parkloc command that must fail: exit status 1, nothing on stdout and exactly one
# line on stderr. Prints "rejected with exit 1: <that line>" for CTest's
# PASS_REGULAR_EXPRESSION to check the message, or "UNEXPECTED: ..." otherwise.
out=$(mktemp) err=$(mktemp)
"$@" >"$out" 2>"$err"
rc=$?
lines=$(wc -l <"$err")
if [ "$rc" -eq 1 ] && [ "$lines" -eq 1 ] && [ ! -s "$out" ]; then
  printf 'rejected with exit 1: %s\n' "$(cat "$err")"
else
  printf 'UNEXPECTED: exit %s, %s stderr line(s), stdout %s bytes\n' "$rc" "$lines" "$(wc -c <"$out")"
  cat "$err"
fi
rm -f "$out" "$err"
