#!/usr/bin/env bash
# The README's main-job command: installs what is missing, builds the release
# configuration and runs the ASR-V example (examples/asr-v/run.sh) into an
# SQLite database, printing its results.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$root/scripts/build.sh" release
exec bash "$root/examples/asr-v/run.sh" "$root/build/release/hydrocoef" "$root/build/asr-v.db"
