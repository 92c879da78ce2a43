#!/usr/bin/env bash
# tools/fuzz.sh judges a fuzz report by its first frame past the sanitizer's and libFuzzer's
# own: each report in tests/fuzz/reports/ must be judged as its name says (third_party_*:
# listed, not failing; emb_*: a finding that fails the run).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
failures=0
count=0
for log in "$root"/tests/fuzz/reports/*.log; do
  name=$(basename "$log")
  case "$name" in
    third_party_*) want=third-party ;;
    emb_*) want=emb ;;
    *) echo "FAIL: $name: expected a name starting third_party_ or emb_"; failures=$((failures + 1)); continue ;;
  esac
  verdict=$(bash "$root/tools/fuzz.sh" --classify "$log")
  count=$((count + 1))
  if [[ "${verdict%%:*}" != "$want" ]]; then
    echo "FAIL: $name judged '$verdict', expected $want"
    failures=$((failures + 1))
  else
    echo "ok: $name -> $want"
  fi
done
[[ $count -ge 4 ]] || { echo "FAIL: only $count reports"; exit 1; }
exit $((failures > 0))
