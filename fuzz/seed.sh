#!/bin/sh
# Seeds the fuzz corpus with the repository's own models and test files (one file each).
set -e
cd "$(dirname "$0")"
mkdir -p corpus/check
for f in ../models/*.vhd ../tests/*/*.vhd ../stdlib/*/*.vhd; do
  cp "$f" "corpus/check/$(echo "$f" | tr '/.' '__')"
done
echo "$(ls corpus/check | wc -l) seed files in fuzz/corpus/check"
