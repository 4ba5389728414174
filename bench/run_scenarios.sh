#!/usr/bin/env bash
# Whole-scenario benchmarks: times runs of the ancfnet CLI over bench/scenes/*.yaml and compares
# them with the Project Chrono anchors (shared/reference/anchor-figures.md). Prints Markdown tables
# ready to paste into docs/benchmarks.md; raw results (hyperfine JSON/Markdown, summary.json of
# every run, /usr/bin/time -v logs, Google Benchmark JSON) go to RESULTS_DIR.
#
# Usage: bench/run_scenarios.sh BUILD_DIR [RESULTS_DIR]   (default RESULTS_DIR: BUILD_DIR/bench-results)
# Environment: RUNS (default 5) timed runs per scene; KERNELS=0 skips the Google Benchmark kernels;
# NETS=1 also runs the net deployment benchmarks (bench/run_net_scenarios.sh, bench/net_scenes/,
# about 30 min; results in RESULTS_DIR/nets).
# Needs hyperfine and GNU time (scripts/install-deps.sh --bench) and /usr/bin/python3.
set -euo pipefail

if [ $# -lt 1 ] || [ $# -gt 2 ]; then
  echo "usage: $0 BUILD_DIR [RESULTS_DIR]" >&2
  exit 2
fi
build_dir=$(cd "$1" && pwd)
results=${2:-$build_dir/bench-results}
runs=${RUNS:-5}
bench_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo=$(dirname "$bench_dir")
cli=$build_dir/apps/ancfnet/ancfnet
kernels=$build_dir/bench/ancfnet_bench

[ -x "$cli" ] || { echo "$0: no CLI at $cli (build first)" >&2; exit 2; }
for tool in hyperfine /usr/bin/time /usr/bin/python3; do
  command -v "$tool" >/dev/null || {
    echo "$0: $tool is missing (scripts/install-deps.sh --bench)" >&2
    exit 2
  }
done
[ "$runs" -ge 5 ] || { echo "$0: RUNS must be at least 5" >&2; exit 2; }

rm -rf "$results"
mkdir -p "$results"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# What the figures come from: commit, build, machine.
commit=$(git -C "$repo" rev-parse --short HEAD 2>/dev/null || echo unknown)
# Paths with uncommitted changes, the first six named.
changed=$(git -C "$repo" --no-optional-locks status --short 2>/dev/null | awk '{print $NF}' || true)
if [ -n "$changed" ]; then
  listed=$(echo "$changed" | head -6 | paste -sd ' ' -)
  [ "$(echo "$changed" | wc -l)" -le 6 ] || listed="$listed …"
  commit="$commit with uncommitted changes ($listed)"
fi
cache=$build_dir/CMakeCache.txt
cache_value() { { sed -n "s/^$1:[A-Z]*=//p" "$cache" 2>/dev/null || true; } | head -1; }
build_type=$(cache_value CMAKE_BUILD_TYPE)
build_type_upper=$(echo "$build_type" | tr '[:lower:]' '[:upper:]')
compiler=$(cache_value CMAKE_CXX_COMPILER)
flags=$(echo "$(cache_value CMAKE_CXX_FLAGS) $(cache_value "CMAKE_CXX_FLAGS_$build_type_upper")" | xargs)
{
  echo "- state (source tree at run time; make bench rebuilds first): $commit"
  echo "- date: $(date -u +%Y-%m-%dT%H:%MZ)"
  echo "- CPU: $(lscpu | sed -n 's/^Model name: *//p' | head -1), $(env -u OMP_NUM_THREADS -u OMP_THREAD_LIMIT nproc) cores;" \
       "memory $(free -h | awk '/^Mem:/ {print $2}')"
  echo "- compiler: $("$compiler" --version 2>/dev/null | head -1);" \
       "$build_type, flags '$flags'"
  echo "- OMP_NUM_THREADS=1; $runs timed runs per scene after 1 warm-up; medians"
  echo "- load average at start: $(cut -d' ' -f1-3 /proc/loadavg) (other jobs inflate wall times)"
} >"$results/machine.md"
export OMP_NUM_THREADS=1

# Kernels (Google Benchmark), medians of 5 repetitions.
if [ "${KERNELS:-1}" != 0 ] && [ -x "$kernels" ]; then
  echo "kernels: $kernels" >&2
  "$kernels" --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
    --benchmark_out="$results/kernels.json" --benchmark_out_format=json >&2
fi

failed=()
for scene in "$bench_dir"/scenes/*.yaml; do
  name=$(basename "$scene" .yaml)
  out=$tmp/$name
  echo "scene: $name" >&2
  # Solver time (summary.json) and peak RSS: runs under GNU time, every summary kept.
  ok=1
  for i in $(seq 1 "$runs"); do
    if ! /usr/bin/time -v -o "$results/$name.time.$i.txt" "$cli" run "$scene" -o "$out" -q; then
      ok=0
      break
    fi
    cp "$out/summary.json" "$results/$name.summary.$i.json"
  done
  cp "$out/probes.csv" "$results/$name.probes.csv" 2>/dev/null || true
  if [ "$ok" = 0 ]; then
    echo "$0: $name failed; skipping its hyperfine timing" >&2
    failed+=("$name")
    continue
  fi
  # Whole process (start-up, scene loading, solve, output) with hyperfine.
  hyperfine --style basic --warmup 1 --runs "$runs" --command-name "$name" \
    --export-json "$results/$name.hyperfine.json" \
    --export-markdown "$results/$name.hyperfine.md" \
    "'$cli' run '$scene' -o '$out' -q" >&2
done

/usr/bin/python3 - "$results" <<'EOF' | tee "$results/tables.md"
import glob, json, re, statistics, sys

results = sys.argv[1]
L = 1.0  # every bench scene has a 1 m cable along +x from the origin
# Project Chrono anchors, shared/reference/anchor-figures.md: (time s, tip u/L, tip w/L).
S1 = {4: (1.7e-3, 0.547747, 0.799804), 8: (3.9e-3, 0.553985, 0.809128),
      16: (7.7e-3, 0.554972, 0.810650)}
S2 = {8: (54, 0.27), 32: (198, 0.91), 128: (774, 3.61)}
S1_EXACT_W = 0.81061  # elastica, k = 10 (tests/verification/elastica_test.cpp)
S2_TIP_REF = (-0.0877, -0.9961)  # (x, z) at t = 0.5 s, Chrono, 128 elements, dt = 1e-4
TARGET = 5.0

def median(xs):
    return statistics.median(xs) if xs else float("nan")

def scene(name):
    summaries = [json.load(open(f)) for f in sorted(glob.glob(f"{results}/{name}.summary.*.json"))]
    rss, cpu = [], []
    for f in glob.glob(f"{results}/{name}.time.*.txt"):
        text = open(f).read()
        m = re.search(r"Maximum resident set size \(kbytes\): (\d+)", text)
        if m:
            rss.append(int(m.group(1)) / 1024.0)
        m = re.search(r"Percent of CPU this job got: (\d+)%", text)
        if m:
            cpu.append(int(m.group(1)))
    hf = None
    try:
        hf = json.load(open(f"{results}/{name}.hyperfine.json"))["results"][0]
    except (OSError, KeyError, IndexError, ValueError):
        pass
    return summaries, rss, cpu, hf

def ratio(chrono, ours):
    r = chrono / ours
    return f"**{r:.1f}×**" + ("" if r >= TARGET else " (< 5×)")

def tip_at(name, t):
    try:
        with open(f"{results}/{name}.probes.csv") as f:
            header = f.readline().strip().split(",")
            rows = [list(map(float, line.split(","))) for line in f if line.strip()]
        row = min(rows, key=lambda r: abs(r[0] - t))
        return row[header.index("tip.x")], row[header.index("tip.z")]
    except (OSError, ValueError, IndexError):
        return float("nan"), float("nan")

print(open(f"{results}/machine.md").read())

# Kernels.
try:
    data = json.load(open(f"{results}/kernels.json"))
    print("### Kernels (Google Benchmark, median of 5 repetitions)\n")
    print("| kernel | median time |")
    print("|---|---:|")
    scale = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}
    for b in data["benchmarks"]:
        if b.get("aggregate_name") == "median":
            t = b["real_time"] * scale[b.get("time_unit", "ns")]
            shown = f"{t*1e9:.0f} ns" if t < 1e-5 else f"{t*1e6:.1f} µs"
            print(f"| `{b['run_name']}` | {shown} |")
    print()
except (OSError, ValueError, KeyError):
    pass

rows_process = []
print("### S1 static cantilever, k = 10, full load in one solve\n")
print("| elements | our solve time (ms) | Newton iterations | tip u/L | tip w/L | error w "
      "| Chrono time (ms) | Chrono u/L | Chrono w/L | Chrono error w | speed-up |")
print("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
for n, (t_c, u_c, w_c) in S1.items():
    name = f"cantilever_k10_{n}"
    summaries, rss, cpu, hf = scene(name)
    rows_process.append((name, summaries, rss, cpu, hf))
    if not summaries or summaries[-1]["status"] != "completed":
        print(f"| {n} | FAILED | | | | | {t_c*1e3:.1f} | {u_c} | {w_c} | | |")
        continue
    t = median([s["wall_time_s"] for s in summaries])
    x, _, z = summaries[-1]["probes"]["tip"]["position"]
    print(f"| {n} | {t*1e3:.2f} | {summaries[-1]['newton_iterations']} | {(L - x)/L:.6f} "
          f"| {-z/L:.6f} | {-z/L - S1_EXACT_W:+.2e} | {t_c*1e3:.1f} | {u_c:.6f} | {w_c:.6f} "
          f"| {w_c - S1_EXACT_W:+.1e} | {ratio(t_c, t)} |")

print("\n### S2 flexible pendulum, 1 s at h = 1e-3 s\n")
print("| elements | DOF | our time loop (s) | steps | Newton it./step | Jacobian updates "
      "| tip (x, z) at t = 0.5 s (m) | Chrono time loop (s) | speed-up |")
print("|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
for n, (dof, t_c) in S2.items():
    name = f"pendulum_{n}"
    summaries, rss, cpu, hf = scene(name)
    rows_process.append((name, summaries, rss, cpu, hf))
    if not summaries or summaries[-1]["status"] != "completed":
        print(f"| {n} | {dof} | FAILED | | | | | {t_c:.2f} | |")
        continue
    s = summaries[-1]
    t = median([x["wall_time_s"] for x in summaries])
    x, z = tip_at(name, 0.5)
    print(f"| {n} | {dof} | {t:.3f} | {s['steps']} | {s['newton_iterations']/s['steps']:.2f} "
          f"| {s['jacobian_updates']} | ({x:.4f}, {z:.4f}) | {t_c:.2f} | {ratio(t_c, t)} |")
print(f"\nChrono tip at t = 0.5 s (128 elements, h = 1e-4): ({S2_TIP_REF[0]}, {S2_TIP_REF[1]}) m.")

print("\n### Whole process (hyperfine) and peak memory\n")
print("| scene | process median (ms) | min–max (ms) | CPU share of wall time, median "
      "| solver wall_time_s median (ms) | peak RSS (MiB) |")
print("|---|---:|---:|---:|---:|---:|")
for name, summaries, rss, cpu, hf in rows_process:
    if not summaries or not hf:
        print(f"| {name} | FAILED | | | | |")
        continue
    solve = median([s["wall_time_s"] for s in summaries]) * 1e3
    proc = f"{hf['median']*1e3:.1f} | {hf['min']*1e3:.1f}–{hf['max']*1e3:.1f}"
    proc += f" | {median(cpu):.0f} %" if cpu else " | —"
    peak = f"{max(rss):.1f}" if rss else "—"
    print(f"| {name} | {proc} | {solve:.2f} | {peak} |")
EOF

if [ "${NETS:-0}" = 1 ]; then
  echo "net deployment benchmarks (bench/run_net_scenarios.sh)" >&2
  "$bench_dir/run_net_scenarios.sh" "$build_dir" "$results/nets" || failed+=(nets)
fi

if [ ${#failed[@]} -gt 0 ]; then
  echo "$0: failed scenes: ${failed[*]}" >&2
  exit 1
fi
echo "results in $results" >&2
