#!/usr/bin/env bash
# Installs every build, test and tool dependency of JTracer from Debian 12 packages.
# Safe to run again: when everything is already present it does nothing.
set -euo pipefail

packages=(
    build-essential cmake ninja-build pkg-config clang-format ccache
    libglm-dev libtbb-dev libembree-dev libcli11-dev libstb-dev libturbojpeg0-dev libjpeg62-turbo-dev libpng-dev zlib1g-dev libassimp-dev nlohmann-json3-dev assimp-testmodels
    libgtest-dev libgmock-dev libbenchmark-dev
    libglfw3-dev libimgui-dev libosmesa6-dev libgl-dev xvfb xauth fonts-dejavu-core
    libopenmpi-dev openmpi-bin iproute2
    clang libclang-rt-14-dev valgrind
    tachyon-bin-nox
    mandoc man-db dpkg-dev file bash-completion zsh desktop-file-utils shared-mime-info
    python3 python3-dev pybind11-dev python3-numpy python3-pytest
)

missing=()
for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
    echo "install-deps: all ${#packages[@]} packages present"
    exit 0
fi

sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
echo "install-deps: installing ${missing[*]}"
"${sudo_cmd[@]}" apt-get update -qq
DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
