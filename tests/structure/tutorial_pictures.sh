#!/usr/bin/env bash
# docs/tutorial.md and its pictures agree: every picture it shows is committed, and every committed
# picture under docs/images/tutorial/ is made by one of the tutorial's own `rayvec` command lines
# (an `-o` path, or a `--heatmap` PNG named after its EXR), which scripts/make_tutorial_images.sh runs.
# Usage: tutorial_pictures.sh REPOSITORY_ROOT
set -euo pipefail
root="$1"
doc="$root/docs/tutorial.md"
status=0
commands=$(awk '/^```sh$/ {on = 1; next} /^```$/ {on = 0} on && /^rayvec / {print}' "$doc")
[[ -n "$commands" ]] || { echo "FAIL: no rayvec commands in docs/tutorial.md"; exit 1; }
while IFS= read -r img; do
  [[ -f "$root/docs/$img" ]] || { echo "FAIL: docs/tutorial.md shows $img, which is not in the repository"; status=1; }
done < <(grep -oE '\(images/tutorial/[^)]+\.png\)' "$doc" | tr -d '()')
made=$(echo "$commands" | grep -oE -- '-o docs/images/tutorial/[^ ]+' | sed 's/^-o //')
while IFS= read -r exr; do
  for channel in nodes triangles bounces; do made+=$'\n'"${exr%.exr}.$channel.png"; done
done < <(echo "$commands" | grep -- '--heatmap' | grep -oE -- '-o docs/images/tutorial/[^ ]+\.exr' | sed 's/^-o //')
for png in "$root"/docs/images/tutorial/*.png; do
  rel="docs/images/tutorial/$(basename "$png")"
  grep -qxF "$rel" <<<"$made" || { echo "FAIL: $rel is made by no command in docs/tutorial.md"; status=1; }
done
[[ $status -eq 0 ]] && echo "tutorial pictures: $(grep -c . <<<"$made") made by its commands, all present"
exit $status
