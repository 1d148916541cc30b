#!/bin/bash
# The README's live test cell sequence, run as written: the lines of its ```sh block after the
# marker "live-cell sequence", in a scratch folder where build/, data/ and deploy/ are this
# tree's, on a DDS domain of this run (--domain N added to the programs that join one).
# Passes when swap-model reports the diagnosed model in force.
# Usage: readme_live_cell_test.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build_dir=$(cd "$1" && pwd)
source_dir=$(cd "$2" && pwd)
. "$source_dir/tests/claim_domain.sh"
claim_domain domain 9   # as tests/service/service_process.cc: 1-200, one per process
scratch=$(mktemp -d /tmp/gc_readme_live.XXXXXX)
trap 'kill $(jobs -p) 2>/dev/null || true; rm -rf "$scratch"' EXIT
ln -s "$build_dir" "$scratch/build"
ln -s "$source_dir/data" "$scratch/data"
ln -s "$source_dir/deploy" "$scratch/deploy"

awk '/<!-- live-cell sequence/ {marked = 1; next}
     marked && /^```sh$/ {inside = 1; next}
     inside && /^```$/ {exit}
     inside {print}' "$source_dir/README.md" > "$scratch/sequence.sh"
grep -q 'swap-model' "$scratch/sequence.sh" || { echo "no live-cell sequence in README.md"; exit 1; }
# The domain of this run, after each program that joins one.
sed -i -E "s#(gearcoupling-monitor|gearcoupling (record|replay|swap-model))( |\$)#\1 --domain $domain\3#" \
  "$scratch/sequence.sh"
echo "--- the README's sequence, on domain $domain:"
cat "$scratch/sequence.sh"
echo "---"
cd "$scratch"
# Bounded: the sequence itself takes about 15 s.
timeout 90 bash -e sequence.sh > output.txt 2>&1 || { cat output.txt; echo "the sequence failed"; exit 1; }
cat output.txt
grep -q '^test cell dyno: model paper_diagnosed in force$' output.txt ||
  { echo "FAIL: swap-model did not report the diagnosed model in force"; exit 1; }
echo "PASS: the swap is in force while the replay runs"
