# Sourced by the CLI tests (not a test itself): expect_error CASE SED_SCRIPT PATTERN KEY writes
# $scene edited by SED_SCRIPT to $work/CASE.yaml, runs `$ancfnet check` on it and fails (with the
# caller's `fail`) unless it exits with 2 and one line FILE:LINE:COL that names KEY, LINE being
# the first line of the edited scene matching PATTERN.
expect_error() {
  local case="$1" sed_script="$2" pattern="$3" key="$4"
  local file="$work/$case.yaml" status=0
  sed -e "$sed_script" "$scene" >"$file"
  ! cmp -s "$scene" "$file" || fail "$case: test setup: '$sed_script' changed nothing"
  local line
  line="$(grep -n -m1 -E -- "$pattern" "$file" | cut -d: -f1)"
  "$ancfnet" check "$file" >/dev/null 2>"$work/stderr" || status=$?
  local message
  message="$(cat "$work/stderr")"
  [[ $status -eq 2 ]] || fail "$case: exit $status, expected 2: $message"
  [[ $(wc -l <"$work/stderr") -eq 1 ]] || fail "$case: stderr is not one line: $message"
  [[ $message =~ $case\.yaml:$line:[0-9]+: ]] || fail "$case: expected line $line in: $message"
  [[ $message == *"$key"* ]] || fail "$case: the message does not name '$key': $message"
}
