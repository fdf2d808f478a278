#!/usr/bin/env bash
# Lists every GoogleTest test that skipped in the last ctest run of a build folder and fails if any
# skip does not name missing hardware or a missing privilege. ctest counts a skip as no failure (and a
# sanitizer shard, one process for many tests, as a pass), so a test that stopped testing would go
# unnoticed; a skip is allowed only with a message that starts "needs hardware:" or "needs privilege:"
# (GTEST_SKIP() << "needs privilege: ..."; docs/contributing.md).
#
# Usage: tests/check_skips.sh BUILD_DIR   (after ctest ran there; reads Testing/Temporary/LastTest.log)
set -euo pipefail

if [[ $# -ne 1 ]]; then
  echo "usage: $0 BUILD_DIR" >&2
  exit 2
fi
log="$1/Testing/Temporary/LastTest.log"
if [[ ! -f "$log" ]]; then
  echo "$0: no ctest log at $log" >&2
  exit 2
fi

# GoogleTest prints a skip as "FILE:LINE: Skipped", the message's lines, then "[  SKIPPED ] NAME (N ms)".
# The message is its first line; the closing summary's "[  SKIPPED ] NAME" lines (no time) are left out.
skips=$(awk '
  / Skipped$/ { want = 1; message = ""; next }
  want == 1 { message = $0; want = 0; next }
  /^\[  SKIPPED \] [^ ]+ \([0-9]+ ms\)$/ { print $4 "\t" message; message = "" }
' "$log" | sort -u)

if [[ -z "$skips" ]]; then
  echo "=== skipped tests: none"
  exit 0
fi
echo "=== skipped tests:"
bad=0
while IFS=$'\t' read -r name message; do
  case "$message" in
    "needs hardware:"* | "needs privilege:"*) echo "  $name: $message" ;;
    *) echo "  $name: $message   <- NOT ALLOWED: a skip must name missing hardware or a missing privilege"; bad=1 ;;
  esac
done <<< "$skips"
exit "$bad"
