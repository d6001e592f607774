#!/usr/bin/env bash
# Every pass type's tests are findable by its name: for each pass type
# `volgraph passes` lists, some tests/<kind>/<pass>_test.cpp or tests/<kind>/<pass>_*_test.cpp
# exists, or tests/passes_tested_elsewhere.txt names the file that holds its tests and why.
# An allow-list entry must name an existing file and a pass that has no file of its own
# (a stale entry hides the next missing one). The control: the same check with one more,
# made-up pass type must fail and name it (a new pass without tests is caught).
#   tests_named_after_passes_test.sh <volgraph binary> <source root>
set -euo pipefail
volgraph="$1" root="$2"
allow="$root/tests/passes_tested_elsewhere.txt"

# check PASS...: prints one line per pass without tests; status 1 if any.
check() {
  local status=0 pass file
  for pass in "$@"; do
    if compgen -G "$root/tests/*/${pass}_test.cpp" >/dev/null || compgen -G "$root/tests/*/${pass}_*_test.cpp" >/dev/null; then
      if grep -Eq "^${pass}[[:space:]]" "$allow"; then
        echo "$allow: the entry for $pass is stale: tests/*/${pass}_test.cpp exists; remove the entry"
        status=1
      fi
      continue
    fi
    file="$(awk -v p="$pass" '$1 == p { print $2; exit }' "$allow")"
    if [ -z "$file" ]; then
      echo "no tests for the pass type $pass: expected tests/<kind>/${pass}_test.cpp (or ${pass}_<what>_test.cpp), or a line \"$pass <test file> <why>\" in $allow"
      status=1
    elif [ ! -f "$root/$file" ]; then
      echo "$allow: the entry for $pass names $file, which does not exist"
      status=1
    fi
  done
  return $status
}

[ -f "$allow" ] || { echo "no allow-list $allow (expected: lines \"<pass> <test file> <why>\")"; exit 1; }
mapfile -t passes < <("$volgraph" passes | grep -E '^[a-z0-9_]+ \(' | cut -d' ' -f1)
[ "${#passes[@]}" -gt 0 ] || { echo "$volgraph passes listed no pass type"; exit 1; }

# Every allow-list entry is a pass type that exists (a removed pass leaves no entry behind).
while read -r pass file _; do
  case "$pass" in ''|'#'*) continue ;; esac
  printf '%s\n' "${passes[@]}" | grep -qx "$pass" || { echo "$allow: $pass is not a pass type \`volgraph passes\` lists"; exit 1; }
done <"$allow"

check "${passes[@]}"

# The control: a pass type nobody wrote tests for is caught, by name.
fake=fake_pass_without_tests
if out="$(check "${passes[@]}" "$fake")"; then
  echo "control failed: the check accepted the pass type $fake, which has no tests"
  exit 1
fi
grep -q "no tests for the pass type $fake:" <<<"$out" || { echo "control failed: the message does not name $fake: $out"; exit 1; }
echo "${#passes[@]} pass types, each with its tests findable by name"
