#!/usr/bin/env bash
# The speed of path mode against Blender's Cycles as a paired series: PAIRS times, Cycles
# renders the anchor's Cornell box (render alone, 2 threads) and then our `rt render` renders
# it (the whole process, 2 workers), once as the scene says (Russian roulette off) and once
# with roulette on, as Cycles always plays it; each pair's ratio is taken as it comes, and the
# medians are printed last. A pair's two renders run seconds apart, so a machine whose speed
# drifts moves both; one run of the anchor's measure.sh (the lower of two times each) swings
# by a fifth on this project's shared 2-core machine. Run from the project's root with nothing
# else busy; Blender stays out of npm test (docs/path-tracing.md, "Speed").
#   bash bench/cycles-speed.sh [PAIRS] [SPP] [W H]
set -euo pipefail
anchor=${ANCHOR:-../shared/anchors/cycles-cornell}
pairs=${1:-10}; spp=${2:-64}; W=${3:-256}; H=${4:-256}
command -v blender >/dev/null || { echo "Blender is missing: apt-get install -y blender" >&2; exit 1; }
scene=$(realpath "$anchor/cornell.scene.json")
out=build/cycles/speed; mkdir -p "$out"
# The anchor's box with Cycles' strategies: cosine bounces, light sampling, roulette.
node bench/strategy-variant.mjs "$scene" "$out/cornell-roulette.json" cosine true true

cycles_ms() {
  blender -b --factory-startup -noaudio -P "$anchor/scene2cycles.py" -- "$scene" "$out/cycles.f32" "$spp" "$1" 2 "$W" "$H" 2>&1 |
    sed -n 's/^CYCLES_SECONDS \([0-9.]*\).*/\1/p' | awk '{ printf "%d", $1 * 1000 }'
}
ours_ms() {
  local started
  started=$(date +%s%N)
  npm run -s rt -- render "$1" --out "$out/ours.pfm" --samples "$spp" --seed "$2" --workers 2 --width "$W" --height "$H" >/dev/null
  echo $((($(date +%s%N) - started) / 1000000))
}

ratios=()
for i in $(seq 1 "$pairs"); do
  c=$(cycles_ms $((i + 10)))
  plain=$(ours_ms "$scene" $((i + 20)))
  roulette=$(ours_ms "$out/cornell-roulette.json" $((i + 20)))
  ratios+=("$c $plain $roulette")
  echo "pair $i: Cycles $c ms, ours $plain ms (no roulette) and $roulette ms (roulette); load $(cut -d' ' -f1 /proc/loadavg)"
done
printf '%s\n' "${ratios[@]}" | node -e '
const rows = require("fs").readFileSync(0, "utf8").trim().split("\n").map((line) => line.split(" ").map(Number));
const median = (values) => { const s = [...values].sort((a, b) => a - b); const m = s.length >> 1; return s.length % 2 ? s[m] : (s[m - 1] + s[m]) / 2; };
const spread = (values) => `${Math.min(...values).toFixed(2)}x to ${Math.max(...values).toFixed(2)}x`;
const plain = rows.map(([c, p]) => p / c), roulette = rows.map(([c, , r]) => r / c);
const ms = (column) => median(rows.map((row) => row[column])).toFixed(0);
console.log(`${rows.length} pairs, ${process.argv[1]} paths per pixel at ${process.argv[2]}x${process.argv[3]}: our whole rt render process over Cycles render alone`);
console.log(`  medians: Cycles ${ms(0)} ms, ours ${ms(1)} ms (no roulette) and ${ms(2)} ms (roulette)`);
console.log(`  as the scene says (no roulette): median ${median(plain).toFixed(2)}x (${spread(plain)}), over 2x in ${plain.filter((r) => r > 2).length}`);
console.log(`  with roulette, as Cycles plays:  median ${median(roulette).toFixed(2)}x (${spread(roulette)}), over 2x in ${roulette.filter((r) => r > 2).length}`);
' "$spp" "$W" "$H"
