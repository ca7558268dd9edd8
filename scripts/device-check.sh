#!/usr/bin/env bash
# make device-check: the GPU tests of every configuration and the benchmarks on whatever Vulkan and EGL drivers this
# machine has (issue 44, "A real GPU": lavapipe forgives missing barriers that a real GPU punishes), written to
# OUT/report.md and OUT/report.json: each configuration's API and device, whether it is hardware, every failing test
# with its message, each benchmark figure (beside a baseline report's, given one), and a short summary on stdout.
# Within 8 minutes on one GPU: every stage runs under a time limit and a stage cut short is reported as a failure.
#
#   scripts/device-check.sh [--quick] [--build DIR] [--out DIR] [--baseline REPORT.json]
#
# --quick: one test suite on the vulkan and opengl configurations and the smallest benchmarks, in about 10 s on
# lavapipe and llvmpipe: what `make test` runs (ctest device-check.quick), so that the script cannot rot.
# --baseline: a report.json of an earlier run (the software rasterizers' on a CI machine, say) whose figures the
# report puts beside this run's.
# Exit status: 0 when every test passed and every stage finished, 1 otherwise, 2 for bad arguments.
set -euo pipefail

quick=0
build=build
out=out/device-check
baseline=
while [ $# -gt 0 ]; do
    case $1 in
    --quick) quick=1 ;;
    --build) build=$2; shift ;;
    --out) out=$2; shift ;;
    --baseline) baseline=$2; shift ;;
    *) echo "device-check: unknown argument '$1' (--quick, --build DIR, --out DIR, --baseline FILE)" >&2; exit 2 ;;
    esac
    shift
done
root=$(cd "$(dirname "$0")/.." && pwd)
penumbra=$build/bin/penumbra
tests=$build/tests
for tool in "$penumbra" "$tests/penumbra_gpu_tests"; do
    [ -x "$tool" ] || { echo "device-check: $tool is not built (make build)" >&2; exit 2; }
done
rm -rf "$out"
mkdir -p "$out/tests"
out=$(cd "$out" && pwd)
started=$(date +%s)
# The tools' pipeline cache in a folder of the run's own: the figures of a first frame are then cold ones.
export PENUMBRA_PIPELINE_CACHE=$out/pipeline-cache
stages=$out/stages.tsv # stage, exit status, seconds
: >"$stages"

# Runs "$@" as stage $1 under a limit of $2 seconds, its output in OUT/<stage>.log.
stage() {
    local name=$1 limit=$2
    shift 2
    local begin status=0
    begin=$(date +%s)
    timeout --kill-after=10 "$limit" "$@" >"$out/$name.log" 2>&1 || status=$?
    printf '%s\t%s\t%s\n' "$name" "$status" "$(($(date +%s) - begin))" >>"$stages"
}

stage devices 60 "$penumbra" configurations --devices
cp "$out/devices.log" "$out/devices.tsv"

# The GPU test executables, one process per configuration and executable, as many at once as there are cores;
# each writes GoogleTest's JSON report.
if [ $quick = 1 ]; then
    configurations="vulkan opengl"
    executables="penumbra_gpu_tests"
    filter="PatternTest.*:PipelineCacheTest.*"
else
    configurations=$("$penumbra" configurations)
    executables="penumbra_gpu_tests shadows_gpu/penumbra_shadow_gpu_tests regression/penumbra_regression_tests"
    filter="*"
fi
runs=$out/test-runs.txt
: >"$runs"
for executable in $executables; do
    [ -x "$tests/$executable" ] || continue
    for configuration in $configurations; do
        echo "$tests/$executable --configuration $configuration --gtest_filter=$filter" \
            "--gtest_output=json:$out/tests/$(basename "$executable")-$configuration.json" >>"$runs"
    done
done
if [ $quick = 0 ] && [ -x "$tests/penumbra_parity_tests" ]; then
    echo "$tests/penumbra_parity_tests --gtest_output=json:$out/tests/penumbra_parity_tests.json" >>"$runs"
fi
stage tests $([ $quick = 1 ] && echo 60 || echo 300) \
    xargs -P "$(nproc)" -I{} sh -c "PENUMBRA_TEST_OUTPUT=$out/test-output {} >/dev/null 2>&1 || true" <"$runs"

# The benchmarks: `make bench`, `make bench-forest` and the culling bench, 10 000 cubes culled on the GPU and on the
# CPU in alternated frames of one process (bench --compare-culling), and 100 000 on the GPU for the CPU time per frame
# (quick: a few draws, one frame of the test scene, one pair of the cubes' frames).
if [ $quick = 1 ]; then
    stage bench 30 "$penumbra" bench -s draws -n 100 --min-time 0.01 -c vulkan opengl --json "$out/bench.json"
    stage bench-scene 30 "$penumbra" bench --scene test --backend vulkan,opengl --frames 1 --warmup 0 \
        --json "$out/bench-scene.json"
    stage bench-culling 30 "$penumbra" bench --scene cubes --size 160x90 --backend vulkan,opengl --frames 1 \
        --warmup 0 --compare-culling --json "$out/bench-culling.json"
else
    stage bench 120 "$penumbra" bench --json "$out/bench.json"
    for tiles in 2048 4096; do
        stage bench-forest-$tiles 90 "$penumbra" bench --scene forest --backend vulkan,opengl --frames 10 \
            --warmup 2 --settings "$root/scripts/bench/forest-$tiles-tiles.json" --json "$out/bench-forest-$tiles.json"
    done
    stage bench-culling 90 "$penumbra" bench --scene cubes --size 160x90 --backend vulkan,opengl --frames 40 \
        --warmup 2 --compare-culling --json "$out/bench-culling.json"
    stage bench-culling-100k 90 "$penumbra" bench --scene cubes-100k --size 160x90 --backend vulkan,opengl \
        --frames 3 --warmup 1 --culling gpu --json "$out/bench-culling-100k.json"
fi

python3 - "$out" "$quick" "$(($(date +%s) - started))" "$baseline" <<'EOF'
import glob, json, os, sys

out, quick, seconds, baseline_path = sys.argv[1], sys.argv[2] == "1", int(sys.argv[3]), sys.argv[4]

devices = []
for line in open(os.path.join(out, "devices.tsv")):
    fields = line.rstrip("\n").split("\t")
    if len(fields) == 3:
        name, api, device = fields
        supported = api != "unsupported"
        # Mesa's software rasterizers name themselves: lavapipe and llvmpipe report "llvmpipe (LLVM ...)".
        hardware = supported and not any(s in device for s in ("llvmpipe", "softpipe", "SwiftShader"))
        devices.append({"configuration": name, "api": api if supported else "", "device": device,
                        "supported": supported, "hardware": hardware})

stages = []
for line in open(os.path.join(out, "stages.tsv")):
    name, status, spent = line.rstrip("\n").split("\t")
    stages.append({"stage": name, "exitStatus": int(status), "seconds": int(spent),
                   "timedOut": int(status) in (124, 137)})

tests, failures = 0, []
for path in sorted(glob.glob(os.path.join(out, "tests", "*.json"))):
    run = os.path.basename(path)[:-len(".json")]
    try:
        report = json.load(open(path))
    except ValueError:
        failures.append({"test": run, "message": "the test process ended without a whole report (crashed?)"})
        continue
    for suite in report.get("testsuites", []):
        for case in suite.get("testsuite", []):
            if case.get("result") == "SKIPPED" or case.get("status") == "NOTRUN":
                continue
            tests += 1
            if case.get("failures"):
                failures.append({"test": f"{run}: {suite['name']}.{case['name']}",
                                 "message": case["failures"][0].get("failure", "")[:2000]})
for runs in open(os.path.join(out, "test-runs.txt")):
    report = runs.split("--gtest_output=json:")[1].strip()
    if not os.path.exists(report):
        failures.append({"test": os.path.basename(report)[:-5], "message": "no report: the process did not finish"})
for s in stages:
    if s["exitStatus"] != 0 and s["stage"] != "tests":
        failures.append({"test": f"stage {s['stage']}",
                         "message": "timed out" if s["timedOut"] else f"exit status {s['exitStatus']}"})

def figures(value, path):
    """Every number of a benchmark JSON, named by its path; list items by their configuration (and scenario)."""
    if isinstance(value, bool):
        return
    if isinstance(value, (int, float)):
        yield path, value
    elif isinstance(value, dict):
        for key, item in value.items():
            yield from figures(item, f"{path}.{key}" if path else key)
    elif isinstance(value, list):
        for index, item in enumerate(value):
            label = str(index)
            if isinstance(item, dict):
                label = "/".join(str(item[k]) for k in ("configuration", "scenario", "draws")
                                 if isinstance(item.get(k), (str, int))) or label
            yield from figures(item, f"{path}[{label}]")

benchmarks = []
for path in sorted(glob.glob(os.path.join(out, "bench*.json"))):
    source = os.path.basename(path)[:-len(".json")]
    try:
        for name, value in figures(json.load(open(path)), ""):
            benchmarks.append({"benchmark": source, "figure": name, "value": value})
    except ValueError:
        failures.append({"test": f"benchmark {source}", "message": "unreadable JSON"})

base = {}
if baseline_path:
    for b in json.load(open(baseline_path)).get("benchmarks", []):
        base[(b["benchmark"], b["figure"])] = b["value"]
    for b in benchmarks:
        b["baseline"] = base.get((b["benchmark"], b["figure"]))

report = {"mode": "quick" if quick else "full", "seconds": seconds, "devices": devices, "testsRun": tests,
          "failures": failures, "stages": stages, "benchmarks": benchmarks,
          "baseline": baseline_path or None}
json.dump(report, open(os.path.join(out, "report.json"), "w"), indent=2)

hardware = sorted({d["device"] for d in devices if d["hardware"]})
software = sorted({d["device"] for d in devices if d["supported"] and not d["hardware"]})
with open(os.path.join(out, "report.md"), "w") as md:
    md.write(f"# Device check ({report['mode']}, {seconds} s)\n\n")
    md.write("| configuration | API | device | hardware |\n|---|---|---|---|\n")
    for d in devices:
        md.write(f"| {d['configuration']} | {d['api']} | {d['device']} | {'yes' if d['hardware'] else 'no'} |\n")
    md.write(f"\n## Tests: {tests} run, {len(failures)} failed\n\n")
    for f in failures:
        md.write(f"- **{f['test']}**\n\n  ```\n  {f['message'].strip().replace(chr(10), chr(10) + '  ')}\n  ```\n")
    md.write("\n## Stages\n\n| stage | seconds | exit status |\n|---|---|---|\n")
    for s in stages:
        md.write(f"| {s['stage']} | {s['seconds']} | {s['exitStatus']}{' (timed out)' if s['timedOut'] else ''} |\n")
    md.write("\n## Benchmarks\n\n")
    md.write("| benchmark | figure | value |" + (" baseline |\n|---|---|---|---|\n" if base else "\n|---|---|---|\n"))
    for b in benchmarks:
        row = f"| {b['benchmark']} | {b['figure']} | {b['value']:.4g} |"
        if base:
            row += f" {'' if b['baseline'] is None else format(b['baseline'], '.4g')} |"
        md.write(row + "\n")

print(f"device-check ({report['mode']}): {', '.join(hardware) or 'no hardware device'}"
      f"{' (software: ' + ', '.join(software) + ')' if software else ''}")
print(f"  tests: {tests} run, {len(failures)} failed; benchmarks: {len(benchmarks)} figures; {seconds} s")
# Issue 44's targets: the GPU-culled frame no slower than the CPU path's at 10 000 cubes, and the CPU time per frame.
def scene_runs(name, key="scene"):
    path = os.path.join(out, f"bench-{name}.json")
    try:
        return {run["configuration"]: run for run in json.load(open(path)).get(key, [])}
    except (OSError, ValueError):
        return {}
for configuration, run in ({} if quick else scene_runs("culling", "cullingComparison")).items():
    print(f"  culling, 10 000 cubes, {configuration}: GPU-culled frame {run['gpuFrameMs']:.2f} ms, over the CPU "
          f"path's {run['gpuOverCpu']:.3f} (paired {run['pairedGpuOverCpu']:.3f}); cpuFrameMs {run['gpuCpuFrameMs']:.2f}")
for configuration, run in scene_runs("culling-100k").items():
    print(f"  culling, 100 000 cubes, {configuration}: cpuFrameMs {run['cpuFrameMs']:.2f}")
for f in failures[:10]:
    print(f"  FAILED {f['test']}")
print(f"  report: {os.path.join(out, 'report.md')}")
sys.exit(1 if failures else 0)
EOF
