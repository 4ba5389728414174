#!/usr/bin/env bash
# Net deployment benchmarks (issue 3): times `ancfnet run` on bench/net_scenes/net_deploy_{10,20,40}.yaml
# (5 m square nets of 10 × 10, 20 × 20 and 40 × 40 meshes, 1 s of deployment) and prints the
# Markdown table of docs/benchmarks.md, "Net deployment (issue 3)": solver wall time (median),
# steps, Newton iterations, Jacobian updates, step cuts, elements, unknowns, and the costs per step,
# per step and element, and per Newton iteration and element.
#
# Usage: bench/run_net_scenarios.sh BUILD_DIR [RESULTS_DIR]  (default RESULTS_DIR: BUILD_DIR/bench-results/nets)
# Environment:
#   NET_SIZES        mesh counts to run (default "10 20 40")
#   NET_RUNS         timed runs per size (default 3; medians)
#   NET_RUNS_40      timed runs of the 40 × 40 net (default 1: a 0.25 s run takes about 13 min)
#   NET_END_TIME     simulated time in s of the 10 × 10 and 20 × 20 nets (default 1.0, the scenes' own)
#   NET_END_TIME_40  simulated time of the 40 × 40 net in s (default 0.25; 1.0 for the full second,
#                    about 40 min a run on the machine of docs/benchmarks.md)
# Called by bench/run_scenarios.sh when NETS=1. Timings are wall times on whatever else the machine
# runs: the load average before each run is saved beside it (RESULTS_DIR/*.load.N.txt).
set -euo pipefail

if [ $# -lt 1 ] || [ $# -gt 2 ]; then
  echo "usage: $0 BUILD_DIR [RESULTS_DIR]" >&2
  exit 2
fi
build_dir=$(cd "$1" && pwd)
results=${2:-$build_dir/bench-results/nets}
sizes=${NET_SIZES:-10 20 40}
runs=${NET_RUNS:-3}
runs_40=${NET_RUNS_40:-1}
end_time=${NET_END_TIME:-1.0}
end_40=${NET_END_TIME_40:-0.25}
bench_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo=$(dirname "$bench_dir")
cli=$build_dir/apps/ancfnet/ancfnet

[ -x "$cli" ] || { echo "$0: no CLI at $cli (build first)" >&2; exit 2; }
for tool in /usr/bin/time /usr/bin/python3; do
  command -v "$tool" >/dev/null || { echo "$0: $tool is missing" >&2; exit 2; }
done

rm -rf "$results"
mkdir -p "$results"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

commit=$(git -C "$repo" rev-parse --short HEAD 2>/dev/null || echo unknown)
changed=$(git -C "$repo" --no-optional-locks status --short 2>/dev/null | awk '{print $NF}' || true)
[ -z "$changed" ] || commit="$commit with uncommitted changes ($(echo "$changed" | head -6 | paste -sd ' ' -))"
{
  echo "- state: $commit"
  echo "- date: $(date -u +%Y-%m-%dT%H:%MZ)"
  echo "- CPU: $(lscpu | sed -n 's/^Model name: *//p' | head -1), $(env -u OMP_NUM_THREADS nproc) cores;" \
       "memory $(free -h | awk '/^Mem:/ {print $2}')"
  echo "- OMP_NUM_THREADS=1; $runs timed runs per size, $end_time s simulated (40 × 40: $runs_40 run(s), $end_40 s); medians"
  echo "- load average at start: $(cut -d' ' -f1-3 /proc/loadavg)"
} >"$results/machine.md"
export OMP_NUM_THREADS=1

failed=()
for n in $sizes; do
  name=net_deploy_$n
  scene=$bench_dir/net_scenes/$name.yaml
  [ -f "$scene" ] || { echo "$0: no scene $scene" >&2; exit 2; }
  count=$runs
  end=$end_time
  if [ "$n" = 40 ]; then
    count=$runs_40
    end=$end_40
  fi
  if [ "$end" != 1.0 ] && [ "$end" != 1 ]; then  # the scenes run to 1.0 s
    sed "s/^  end_time: .*/  end_time: $end/" "$scene" >"$tmp/$name.yaml"
    scene=$tmp/$name.yaml
  fi
  # Elements and unknowns, from `ancfnet check` (one cable line per thread).
  "$cli" check "$scene" >"$tmp/check.txt"
  elements=$(awk '/^  cable / {sum += $3} END {print sum + 0}' "$tmp/check.txt")
  unknowns=$(sed -n 's/.* fixed, \([0-9]*\) unknowns.*/\1/p' "$tmp/check.txt")
  echo "{\"meshes\": $n, \"elements\": $elements, \"unknowns\": $unknowns}" >"$results/$name.model.json"
  for i in $(seq 1 "$count"); do
    cut -d' ' -f1-3 /proc/loadavg >"$results/$name.load.$i.txt"
    echo "$name run $i/$count (load $(cat "$results/$name.load.$i.txt"))" >&2
    if ! /usr/bin/time -v -o "$results/$name.time.$i.txt" "$cli" run "$scene" -o "$tmp/$name" -q; then
      failed+=("$name")
      break
    fi
    cp "$tmp/$name/summary.json" "$results/$name.summary.$i.json"
  done
done

/usr/bin/python3 - "$results" $sizes <<'EOF' | tee "$results/tables.md"
import glob, json, re, statistics, sys

results, sizes = sys.argv[1], sys.argv[2:]
print(open(f"{results}/machine.md").read())
print("| meshes | elements | unknowns | simulated (s) | runs | solver wall time, median (s) "
      "| steps | Newton it. | Jacobian updates | step cuts | it./step | Jac./step | per step (ms) | per step and element (µs) "
      "| per Newton it. and element (µs) | load avg before runs | CPU share | process CPU time, median (s) |")
print("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|---:|---:|")
for n in sizes:
    name = f"net_deploy_{n}"
    model = json.load(open(f"{results}/{name}.model.json"))
    summaries = [json.load(open(f)) for f in sorted(glob.glob(f"{results}/{name}.summary.*.json"))]
    if not summaries or summaries[-1]["status"] != "completed":
        print(f"| {n} × {n} | {model['elements']} | {model['unknowns']} | FAILED |" + " |" * 14)
        continue
    loads = [open(f).read().split()[0] for f in sorted(glob.glob(f"{results}/{name}.load.*.txt"))]
    cpu, cpu_time = [], []
    for f in glob.glob(f"{results}/{name}.time.*.txt"):
        text = open(f).read()
        m = re.search(r"Percent of CPU this job got: (\d+)%", text)
        if m:
            cpu.append(int(m.group(1)))
        u = re.search(r"User time \(seconds\): ([0-9.]+)", text)
        k = re.search(r"System time \(seconds\): ([0-9.]+)", text)
        if u and k:
            cpu_time.append(float(u.group(1)) + float(k.group(1)))
    s = summaries[-1]  # the counts are the same in every run (deterministic solver)
    t = statistics.median(x["wall_time_s"] for x in summaries)
    e = model["elements"]
    print(f"| {n} × {n} | {e} | {model['unknowns']} | {s['time']:g} | {len(summaries)} | {t:.1f} "
          f"| {s['steps']} | {s['newton_iterations']} | {s['jacobian_updates']} | {s['step_cuts']} "
          f"| {s['newton_iterations'] / s['steps']:.2f} | {s['jacobian_updates'] / s['steps']:.2f} "
          f"| {t / s['steps'] * 1e3:.2f} | {t / s['steps'] / e * 1e6:.1f} "
          f"| {t / s['newton_iterations'] / e * 1e6:.2f} | {', '.join(loads)} "
          f"| {statistics.median(cpu) if cpu else float('nan'):.0f} % "
          f"| {statistics.median(cpu_time) if cpu_time else float('nan'):.1f} |")
EOF

if [ ${#failed[@]} -gt 0 ]; then
  echo "$0: failed: ${failed[*]}" >&2
  exit 1
fi
echo "results in $results" >&2
