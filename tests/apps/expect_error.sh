#!/usr/bin/env bash
# expect_error.sh REGEX CMD...: passes when CMD exits non-zero and prints exactly one line
# on stderr, which matches REGEX (extended grep). Used for the bad-input app tests.
set -u
regex=$1; shift
err=$("$@" 2>&1 >/dev/null); code=$?
lines=$(printf '%s\n' "$err" | grep -c .)
if [[ $code -eq 0 ]]; then echo "FAIL: exit 0 for: $*"; exit 1; fi
if [[ $lines -ne 1 ]]; then echo "FAIL: expected one error line, got $lines:"; echo "$err"; exit 1; fi
if ! printf '%s\n' "$err" | grep -Eq -- "$regex"; then echo "FAIL: '$err' does not match '$regex'"; exit 1; fi
echo "ok (exit $code): $err"
