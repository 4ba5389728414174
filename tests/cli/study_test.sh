#!/usr/bin/env bash
# `ancfnet study` on one machine: a 2 × 2 grid of a four-step scene (tests/cli/study/) run with
# -j 2 gives the table of its cases in order, the two refused cases failed with their reason,
# and the plot; a study run again after a case lost its result (as a killed study leaves it)
# runs that case alone and writes the same table; a study killed with SIGTERM after its first
# case resumes without redoing the finished cases and writes the table of a study never stopped;
# a bad study file exits with 2 and one line naming its file, line and key.
# Usage: bash tests/cli/study_test.sh <ancfnet binary> <repo root>
set -euo pipefail

ancfnet="${1:?usage: study_test.sh <ancfnet binary> <repo root>}"
root="${2:?usage: study_test.sh <ancfnet binary> <repo root>}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
export OMP_NUM_THREADS=1

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

study="$root/tests/cli/study/grid.yaml"
out="$work/out"
"$ancfnet" study "$study" -o "$out" -j 2 2>"$work/stderr" || fail "exit $?: $(cat "$work/stderr")"
grep -q "study: 4 cases, 0 done before, 4 to run on 2 worker processes" "$work/stderr" ||
  fail "no start line: $(cat "$work/stderr")"
grep -q "study: 4/4 cases done (2 failed), about 0 s left" "$work/stderr" ||
  fail "no progress lines: $(cat "$work/stderr")"
[[ -s "$out/study.png" ]] || fail "no study.png: $(cat "$work/stderr")"

python3 - "$out/study.csv" <<'PY'
import csv, sys

rows = list(csv.DictReader(open(sys.argv[1])))
header = list(rows[0])
assert header[:5] == ["case", "nets[net].velocity[2]", "contact.law.stiffness", "status",
                      "reason"], header
assert "grab.enclosed_fraction" in header and "rates.angular_body[2]" in header, header
expected = [("0", "-4", "100000000", "ok"), ("1", "-4", "-1", "failed"),
            ("2", "-6", "100000000", "ok"), ("3", "-6", "-1", "failed")]
got = [(r["case"], r["nets[net].velocity[2]"], r["contact.law.stiffness"], r["status"])
       for r in rows]
assert got == expected, got
for r in rows:
    if r["status"] == "ok":
        assert r["reason"] == "" and r["time"] == "0.004" and int(r["steps"]) >= 4, r
        assert 0 <= float(r["grab.enclosed_fraction"]) <= 1, r
    else:
        assert r["reason"].startswith("cases/000") and "stiffness" in r["reason"], r
        assert r["time"] == "", r
for cell in open(sys.argv[1]).read().split(","):
    assert "nan" not in cell.lower(), cell
PY

# A study stopped while case 2 ran: its folder has outputs but no case.json.
cp "$out/study.csv" "$work/first.csv"
kept="$(stat -c %y "$out/cases/0000/summary.json")"
rm "$out/cases/0002/case.json" "$out/study.csv"
"$ancfnet" study "$study" -o "$out" 2>"$work/stderr" || fail "resume: exit $?: $(cat "$work/stderr")"
grep -q "study: 4 cases, 3 done before, 1 to run" "$work/stderr" ||
  fail "resume: $(cat "$work/stderr")"
[[ "$(stat -c %y "$out/cases/0000/summary.json")" == "$kept" ]] || fail "case 0 ran again"
[[ -f "$out/cases/0002/case.json" ]] || fail "case 2 did not run again"
cmp "$work/first.csv" "$out/study.csv" || fail "the resumed study's table differs"

# A study killed (SIGTERM) once its first case is done: it exits with 143; run again, it runs only
# the cases without a result, leaves the finished ones alone, and its table is that of a study
# never stopped.
cp "$root/tests/cli/study/base.yaml" "$work/"
cat >"$work/long.yaml" <<'YAML'
scene: base.yaml
set: {analysis.end_time: 0.1}
parameters:
  - {path: 'nets[net].velocity[2]', values: [-3, -3.5, -4, -4.5, -5, -5.5]}
YAML
"$ancfnet" study "$work/long.yaml" -o "$work/whole" -j 2 2>"$work/stderr" ||
  fail "long study: exit $?: $(cat "$work/stderr")"
"$ancfnet" study "$work/long.yaml" -o "$work/killed" -j 1 2>"$work/stderr" &
pid=$!
for _ in $(seq 600); do
  [[ -f "$work/killed/cases/0000/case.json" ]] && break
  sleep 0.05
done
kill -TERM "$pid"
status=0
wait "$pid" || status=$?
[[ $status -eq 143 ]] || fail "killed study: exit $status: $(cat "$work/stderr")"
[[ ! -f "$work/killed/study.csv" ]] || fail "a killed study wrote its table"
kept="$(stat -c %y "$work/killed/cases/0000/summary.json")"
"$ancfnet" study "$work/long.yaml" -o "$work/killed" -j 2 2>"$work/stderr" ||
  fail "resume after kill: exit $?: $(cat "$work/stderr")"
done_before="$(sed -n 's/^study: 6 cases, \([0-9]*\) done before.*/\1/p' "$work/stderr")"
[[ -n "$done_before" && "$done_before" -ge 1 && "$done_before" -lt 6 ]] ||
  fail "resume after kill: $(cat "$work/stderr")"
[[ "$(stat -c %y "$work/killed/cases/0000/summary.json")" == "$kept" ]] ||
  fail "resume after kill: case 0 ran again"
cmp "$work/whole/study.csv" "$work/killed/study.csv" ||
  fail "the table of the killed and resumed study differs from the whole study's"

# A study file with a misspelt key: exit 2, one line with the file, line and key.
printf 'scene: base.yaml\nparameters:\n  - {path: contact.law.stifness, values: [1]}\n' \
  >"$work/typo.yaml"
cp "$root/tests/cli/study/base.yaml" "$work/"
status=0
"$ancfnet" study "$work/typo.yaml" -o "$work/typo" 2>"$work/stderr" || status=$?
[[ $status -eq 2 ]] || fail "typo: exit $status: $(cat "$work/stderr")"
[[ $(wc -l <"$work/stderr") -eq 1 ]] || fail "typo: not one line: $(cat "$work/stderr")"
grep -q "typo.yaml:3:[0-9]*: .*no key 'stifness' in 'contact.law'; did you mean 'stiffness'" \
  "$work/stderr" || fail "typo: $(cat "$work/stderr")"
echo "study: OK"
