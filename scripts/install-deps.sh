#!/usr/bin/env bash
# Installs the Debian 12 packages imasim needs, only those that are missing.
# Idempotent; run as root (make demo / make test call it). Prints what it does.
set -euo pipefail

packages=(
  build-essential cmake make pkg-config git clang-format
  clang libclang-rt-14-dev  # libFuzzer and the sanitizers' runtime for clang (make fuzz)
  libeigen3-dev libcli11-dev nlohmann-json3-dev libtomlplusplus-dev libassimp-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libopenigtlink-dev  # OpenIGTLink messages for devices
  libsdl2-dev libspnav-dev  # gamepads and joysticks, 3D mice
  libboost-math-dev  # the t distribution for the study statistics
  libcairo2-dev libsqlite3-dev  # heat maps and plots as PNG, trainee records
  chromium fonts-dejavu-core  # tests only: the study report loaded as a browser does
  libepoxy-dev libegl-dev libegl-mesa0 libgl1-mesa-dri  # OpenGL 3.3 through EGL, Mesa's llvmpipe
  libglfw3-dev libimgui-dev libstb-dev  # the window, its panels, PNG frames
  xvfb xauth xdotool  # tests only: the window under a virtual display, real key presses
  python3-dev pybind11-dev python3-numpy  # the Python module, for Debian's /usr/bin/python3
  python3-pytest  # tests only: the Python module's tests
)

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$p")
done

if ((${#missing[@]} == 0)); then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
if [[ $(id -u) -ne 0 ]]; then
  echo "install-deps: missing packages and not root; run as root: apt-get install ${missing[*]}" >&2
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}"
