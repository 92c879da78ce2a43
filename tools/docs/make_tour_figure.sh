#!/usr/bin/env bash
# The README tour's picture, docs/images/inline4_traces.png: the main job's results
# (out/inline4.h5, made by `bash tools/setup.sh run`) plotted by the README's own
# engine_plots.py command line, taken from README.md as written, then copied into docs/.
# Sample run (from anywhere):  bash tools/docs/make_tour_figure.sh
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
cd "$root"
if [ ! -f out/inline4.h5 ]; then
  echo "make_tour_figure.sh: out/inline4.h5 is missing; run: bash tools/setup.sh run" >&2
  exit 1
fi
command=$(grep -m1 '^/usr/bin/python3 tools/plots/engine_plots.py out/inline4.h5 ' README.md)
echo "$command"
bash -c "$command --emb build/tools/emb/emb"
mkdir -p docs/images
cp out/plots/inline4_traces.png docs/images/inline4_traces.png
echo "wrote docs/images/inline4_traces.png"
