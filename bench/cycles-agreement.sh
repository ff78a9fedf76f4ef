#!/usr/bin/env bash
# The picture half of the Cycles anchor (../shared/anchors/cycles-cornell/) for path mode's
# eight strategy combinations, with more than one pair of seeds: for each combination
# (bounceSampling cosine/uniform × lightSampling on/off × russianRoulette on/off, or only the
# ones ROULETTE=true|false keeps) our two renders with each seed pair, compared by the anchor's
# compare.py with the Cycles reference that measure.sh cached. No timing and no Cycles render
# here: run measure.sh on the scene once first (it renders and caches the reference).
#   bash bench/cycles-agreement.sh [SCENE.json] [SPP] [W H]      SEEDS="21/22 33/34" by default
set -euo pipefail
anchor=${ANCHOR:-../shared/anchors/cycles-cornell}
scene=$(realpath "${1:-$anchor/cornell.scene.json}")
spp=${2:-64}; W=${3:-256}; H=${4:-256}; ref_spp=${REF_SPP:-1024}
seeds=${SEEDS:-21/22 33/34}
# measure.sh's cache key: the scene's and the Cycles script's bytes, and the image size. Cycles
# ignores the three fields, so the scene's own reference serves every combination.
key=$(cat "$scene" "$anchor/scene2cycles.py" | sha1sum | cut -c1-10)-${W}x${H}
ref=(build/cycles/ref-$key-$ref_spp-1.f32 build/cycles/ref-$key-$ref_spp-2.f32)
[ -f "${ref[0]}" ] && [ -f "${ref[1]}" ] || { echo "no Cycles reference ${ref[0]}: run $anchor/measure.sh $scene $spp $W $H first" >&2; exit 1; }
variants=build/cycles/variants; mkdir -p "$variants"
for bounce in cosine uniform; do
  for light in true false; do
    for roulette in false true; do
      [ -n "${ROULETTE:-}" ] && [ "$roulette" != "$ROULETTE" ] && continue
      name=$(basename "$scene" .json)-$bounce-light-$light-roulette-$roulette
      variant="$variants/$name.json"
      node bench/strategy-variant.mjs "$scene" "$variant" "$bounce" "$light" "$roulette"
      for pair in $seeds; do
        for s in ${pair%/*} ${pair#*/}; do
          npm run -s rt -- render "$variant" --out "$variants/$name-$s.pfm" --force --samples "$spp" --seed "$s" --workers 2 --width "$W" --height "$H" >/dev/null
        done
        echo "== $name, seeds $pair ($(uptime | sed 's/.*load average/load average/'))"
        python3 "$anchor/compare.py" --ours "$variants/$name-${pair%/*}.pfm" "$variants/$name-${pair#*/}.pfm" --ref "${ref[@]}" --size "$W" "$H" || true
      done
    done
  done
done
