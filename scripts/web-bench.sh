#!/usr/bin/env bash
# The browser's speed against the native renderer (docs/performance.md, "In
# the browser"): RUNS times (default 5), in turn, `f2 bench --threads 2` of
# the default scene at 800x600 playing from frame 0, and the page in headless
# chromium at 800x600 with 2 workers (web/test/bench_page.js) playing the
# same frames; then keystroke-to-picture latencies. Prints each run and the
# medians. Needs the native build (build/release), the page (scripts/web.sh
# builds it), chromium and web/test's npm packages. Where the time goes: each
# run also times one thread, `f2 bench --threads 1` against the wasm SIMD
# module alone in node (web/test/bench_module.js), whole frames and chunks.
#
# Usage: scripts/web-bench.sh [RUNS] [FRAMES]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
runs=${1:-5} frames=${2:-48}
f2=${F2:-$root/build/release/apps/cli/f2}
[ -x "$f2" ] || { echo "web-bench: no $f2: cmake --preset release && cmake --build --preset release" >&2; exit 1; }
[ -f "$root/web/dist/index.html" ] || "$root/scripts/web.sh"
[ -d "$root/web/test/node_modules/puppeteer-core" ] || { echo "web-bench: run scripts/install-node-packages.sh" >&2; exit 1; }

work=$(mktemp -d)
server=
for attempt in 1 2 3 4 5; do
  port=$(( 20000 + RANDOM % 20000 ))
  python3 -m http.server "$port" --bind 127.0.0.1 --directory "$root/web/dist" > "$work/server.log" 2>&1 &
  server=$!
  sleep 1
  kill -0 "$server" 2> /dev/null && break
  server=
done
[ -n "$server" ] || { echo "web-bench: python3 -m http.server did not start" >&2; exit 1; }
trap 'kill "$server" 2> /dev/null; rm -rf "$work"' EXIT

echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
for run in $(seq "$runs"); do
  "$f2" bench --threads 2 --size 800x600 --frame 0 --step 1 --frames "$frames" --json > "$work/native$run.json"
  node "$root/web/test/bench_page.js" "http://127.0.0.1:$port/?size=800x600&workers=2" "$frames" 7 > "$work/page$run.json"
  # Where the time goes: one thread, native against the wasm SIMD module in node.
  "$f2" bench --threads 1 --size 800x600 --frame 0 --step 1 --frames "$frames" --json > "$work/native1_$run.json"
  node --no-experimental-fetch "$root/web/test/bench_module.js" "$root/web/dist/f2-simd.js" "$frames" > "$work/module$run.json"
  echo "run $run: native $(cat "$work/native$run.json")"
  echo "run $run: page   $(cat "$work/page$run.json")"
  echo "run $run: native, 1 thread $(cat "$work/native1_$run.json")"
  echo "run $run: module in node, 1 thread $(cat "$work/module$run.json")"
done
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
node - "$work" "$runs" << 'JS'
const fs = require('fs');
const [dir, runs] = process.argv.slice(2);
const read = (name) => Array.from({length: Number(runs)}, (_, i) => JSON.parse(fs.readFileSync(`${dir}/${name}${i + 1}.json`)));
const median = (values) => [...values].sort((a, b) => a - b)[Math.floor((values.length - 1) / 2)];
const native = read('native'), page = read('page'), native1 = read('native1_'), module = read('module');
const m = (list, key) => median(list.map((r) => r[key]));
const ratios = page.map((p, i) => p.fps / native[i].fps);
const f = (x) => x.toFixed(1);
console.log(`medians of ${runs} runs (${page[0].build}, ${page[0].width}x${page[0].height}, ${page[0].frames} frames):`);
console.log(`  native f2 bench --threads 2: ${f(m(native, 'fps'))} frames/s, ${f(m(native, 'ms_median'))} ms a frame ` +
            `(evaluate ${f(m(native, 'ms_eval'))}, build ${f(m(native, 'ms_build'))}, trace ${f(m(native, 'ms_trace'))})`);
console.log(`  page, 2 workers:             ${f(m(page, 'fps'))} frames/s (${f(m(page, 'fpsMean'))} over the run), ` +
            `${f(m(page, 'msMedian'))} ms a frame ` +
            `(each worker computes ${f(m(page, 'workerMs'))}, the rest ${f(m(page, 'overheadMs'))}; ${page[0].chunks} chunks)`);
console.log(`  page / native: ${median(ratios).toFixed(2)} (per run: ${ratios.map((r) => r.toFixed(2)).join(' ')})`);
console.log(`  keystroke to quarter-resolution picture: ${f(m(page, 'latencyMs'))} ms idle, ` +
            `${f(m(page, 'latencyDuringAaMs'))} ms while the anti-aliased picture renders`);
console.log(`  one thread: native ${f(m(native1, 'ms_median'))} ms a frame (CPU ${f(m(native1, 'cpu_ms'))}), ` +
            `the wasm SIMD module in node ${f(m(module, 'wholeMs'))} ms in one call, ${f(m(module, 'chunkedMs'))} ms ` +
            `in 32-row chunks; native 2 threads: CPU ${f(m(native, 'cpu_ms'))} ms a frame`);
console.log(`  keystroke to full picture: ${f(m(page, 'latencyFullMs'))} ms idle, ${f(m(page, 'latencyDuringAaFullMs'))} ms`);
JS
