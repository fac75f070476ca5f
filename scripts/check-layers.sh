#!/usr/bin/env bash
# Enforces the layer order of docs/ARCHITECTURE.md: a layer includes only itself and the
# layers listed for it below (and base/, the floor under them all), never a higher one. The
# programs under apps/ and the Python module under python/ are the top layer: they include any
# layer of src/ (and their own files, by plain name), nothing else.
set -euo pipefail
cd "$(dirname "$0")/.."
declare -A allowed=(
  [base]="base"
  [math]="math"
  [geometry]="geometry math"
  [haptics]="haptics math"
  [devices]="devices haptics math"
  [physics]="physics geometry math"
  [tissue]="tissue physics geometry math"
  [surgery]="surgery tissue physics geometry math"
  [scene]="scene tissue physics geometry math"
  [session]="session scene surgery tissue physics geometry math"
  [metrics]="metrics surgery tissue physics geometry math"
  [autopilot]="autopilot session scene surgery tissue physics geometry math devices haptics"
  [report]="report metrics surgery tissue physics geometry math"
  [render]="render session scene surgery tissue physics geometry math"
  [console]="console session scene surgery tissue physics geometry math devices haptics metrics"
  [runner]="runner console autopilot session scene surgery tissue physics geometry math devices haptics metrics"
  [ui]="ui render runner console session scene surgery tissue physics geometry math devices haptics metrics"
)
# base/ is the floor under every layer: the shared basics (the lock-free hand-off between threads).
for layer in "${!allowed[@]}"; do
  [[ $layer == base ]] || allowed[$layer]+=" base"
done
src_layers="${!allowed[*]}"
allowed[apps]=$src_layers
allowed[python]=$src_layers
bad=0
for layer in "${!allowed[@]}"; do
  dir="src/$layer"
  [[ $layer == apps || $layer == python ]] && dir=$layer
  [[ -d "$dir" ]] || continue
  while IFS=: read -r file line text; do
    inc=$(sed -E 's/.*#include "([a-z_]+)\/.*/\1/' <<<"$text")
    [[ " ${allowed[$layer]} " == *" $inc "* ]] && continue
    echo "check-layers: $file:$line: layer '$layer' includes '$inc'" >&2
    bad=1
  done < <(grep -rnE '#include "[a-z_]+/' "$dir" || true)
done
((bad == 0)) && echo "check-layers: layer order respected"
exit $bad
