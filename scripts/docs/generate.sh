#!/bin/sh
# Regenerates the guide's generated regions (each command's --help in docs/tool.md, the settings reference in
# docs/settings.md) from the built tool: scripts/docs/generate.sh [--check] [build folder, default build].
check=
[ "$1" = --check ] && { check=--check; shift; }
exec python3 "$(dirname "$0")/generate.py" $check --penumbra "${1:-build}/bin/penumbra"
