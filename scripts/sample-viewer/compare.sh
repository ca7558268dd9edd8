#!/bin/sh
# Compares penumbra render's lit pictures with the Khronos glTF Sample Viewer's (compare.mjs), installing on demand
# what that needs and `make test` does not: Debian's chromium (headless, WebGL2 on SwiftShader) and this folder's
# npm packages at package-lock.json's versions. Arguments go to compare.mjs, e.g.
#   scripts/sample-viewer/compare.sh --penumbra build/bin/penumbra --out out/sample-viewer --scenes file.glb
set -eu
here=$(cd "$(dirname "$0")" && pwd)
if [ ! -x /usr/bin/chromium ]; then
    echo "sample-viewer: installing Debian's chromium" >&2
    if [ "$(id -u)" -ne 0 ]; then
        echo "sample-viewer: /usr/bin/chromium is missing; install it as root: apt-get install chromium" >&2
        exit 1
    fi
    apt-get update -q >/dev/null
    DEBIAN_FRONTEND=noninteractive apt-get install -y -q chromium >/dev/null
fi
if ! command -v node >/dev/null || ! command -v npm >/dev/null; then
    echo "sample-viewer: node and npm are needed (scripts/install-deps.sh installs them)" >&2
    exit 1
fi
# npm ci again only when the lock file changed since the last install.
if ! cmp -s "$here/package-lock.json" "$here/node_modules/.penumbra-installed-lock.json" 2>/dev/null; then
    (cd "$here" && npm ci --no-audit --no-fund --loglevel=error)
    cp "$here/package-lock.json" "$here/node_modules/.penumbra-installed-lock.json"
fi
exec node "$here/compare.mjs" "$@"
