# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 GrazeLab developers
# Shared by the command-line tests: needs $cli, $out, $err and a failures counter.

fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# an invalid input: exit 2, nothing on stdout, one line on stderr (containing $EXPECT_WORD)
expect_invalid() {
  "$cli" "$@" >"$out" 2>"$err"
  local code=$?
  if [ "$code" -ne 2 ]; then fail "exit $code, not 2, for: $*"; return; fi
  if [ -s "$out" ]; then fail "stdout not empty for: $*"; fi
  if [ "$(wc -l <"$err")" -ne 1 ]; then fail "stderr is not one line for: $* -> $(cat "$err")"; fi
  if [ -n "${EXPECT_WORD:-}" ] && ! grep -q -- "$EXPECT_WORD" "$err"; then
    fail "stderr lacks '$EXPECT_WORD' for: $* -> $(cat "$err")"
  fi
}

expect_ok() {
  "$cli" "$@" >"$out" 2>"$err"
  local code=$?
  if [ "$code" -ne 0 ]; then fail "exit $code for: $* -> $(cat "$err")"; return 1; fi
  return 0
}
