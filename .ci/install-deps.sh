#!/usr/bin/env bash
# Installs the Debian 12 packages ssaolab needs to build, test and run headless.
# Idempotent: does nothing (and needs no network) when everything is already present.
set -euo pipefail

PKGS=(
  build-essential cmake pkg-config
  libglfw3-dev libglm-dev libimgui-dev libtinygltf-dev libstb-dev
  libegl-dev libgl-dev libepoxy-dev libegl-mesa0 libgl1-mesa-dri libgl1 libglx-mesa0
  nlohmann-json3-dev libtinyexr-dev libcli11-dev zlib1g-dev  # zlib: PNG data inflated and counted before stb decodes it
  libgtest-dev libgmock-dev
  libembree-dev libtbb-dev libbenchmark-dev
  python3 python3-matplotlib
  clang  # libFuzzer targets with ASan+UBSan (tests/fuzz)
  glslang-tools  # glslangValidator: every shader variant compiles offline (tests/gl/test_glsl_validator.cpp)
  assimp-testmodels  # 53 glTF files, many broken on purpose (tests/cli/test_cli.cpp)
  xvfb xauth
  chromium  # report.html opened in a real browser (tests/cli/test_report_html.cpp); the web engines (tune --engine)
)
# Node.js with npm: the web engines' npm packages (make engine-modules) and their driver. Debian 12's
# nodejs is 18, which the pinned playwright-core accepts; a newer Node.js already on PATH (e.g.
# NodeSource's, which bundles npm) is kept rather than replaced.
if ! command -v node >/dev/null || ! command -v npm >/dev/null ||
   [ "$(node -p 'process.versions.node.split(".")[0]' 2>/dev/null || echo 0)" -lt 18 ]; then
  PKGS+=(nodejs npm)
fi

missing=()
for p in "${PKGS[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#PKGS[@]} packages present"
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
