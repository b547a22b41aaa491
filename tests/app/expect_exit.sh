#!/usr/bin/env bash
# expect_exit.sh CODE REGEX COMMAND...: runs COMMAND, fails unless it exits with CODE and (when
# REGEX is not empty) its combined output matches REGEX (extended grep, case-insensitive).
set -u
want="$1"; pattern="$2"; shift 2
out="$("$@" 2>&1)"; got=$?
echo "$out"
if [ "$got" != "$want" ]; then echo "expect_exit: '$*' exited $got, expected $want" >&2; exit 1; fi
if [ -n "$pattern" ] && ! grep -Eqi -- "$pattern" <<<"$out"; then
  echo "expect_exit: output of '$*' does not match /$pattern/" >&2; exit 1
fi
exit 0
