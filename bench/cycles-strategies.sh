#!/usr/bin/env bash
# Runs the Cycles anchor (../shared/anchors/cycles-cornell/measure.sh) once for each of path
# mode's eight strategy combinations — bounceSampling cosine/uniform × lightSampling on/off ×
# russianRoulette on/off — on one scene (default: the anchor's Cornell box). The issue asks
# every combination to agree with Cycles (docs/path-tracing.md, "Checked against Cycles").
#   bash bench/cycles-strategies.sh [SCENE.json] [SPP] [W H]
# Cycles ignores the three fields, so all eight variants share the Cycles reference of the
# first: it is rendered once (REF_SPP paths, two seeds) and linked for the others under the
# names measure.sh looks for, which saves seven slow reference renders. Run it from the
# project's root, with nothing else busy if the times matter; it prints the load average
# beside each run, because the machine is shared.
set -euo pipefail
# The anchor's folder; from a worktree elsewhere: ANCHOR=/path/to/shared/anchors/cycles-cornell.
anchor=${ANCHOR:-../shared/anchors/cycles-cornell}
scene=$(realpath "${1:-$anchor/cornell.scene.json}")
spp=${2:-64}; W=${3:-256}; H=${4:-256}; ref_spp=${REF_SPP:-1024}
variants=build/cycles/variants; mkdir -p "$variants"
# measure.sh's cache key: the scene's and the Cycles script's bytes, and the image size.
key() { cat "$1" "$anchor/scene2cycles.py" | sha1sum | cut -c1-10; }
first=''
for bounce in cosine uniform; do
  for light in true false; do
    for roulette in false true; do
      name=$(basename "$scene" .json)-$bounce-light-$light-roulette-$roulette
      variant="$variants/$name.json"
      node bench/strategy-variant.mjs "$scene" "$variant" "$bounce" "$light" "$roulette"
      if [ -z "$first" ]; then
        first=$(key "$variant")
      else
        for s in 1 2; do
          ln -sf "ref-$first-${W}x${H}-$ref_spp-$s.f32" "build/cycles/ref-$(key "$variant")-${W}x${H}-$ref_spp-$s.f32"
        done
      fi
      echo "== $name ($(uptime | sed 's/.*load average/load average/'))"
      bash "$anchor/measure.sh" "$variant" "$spp" "$W" "$H" || true
    done
  done
done
