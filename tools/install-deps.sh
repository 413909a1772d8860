#!/usr/bin/env bash
# Installs the Debian 12 packages Tunica needs, only those that are missing.
set -euo pipefail
pkgs=(g++ cmake make pkg-config libeigen3-dev libsuitesparse-dev libyaml-cpp-dev libcli11-dev
      libfmt-dev libudunits2-dev zlib1g-dev libopenblas0-pthread libgtest-dev libceres-dev libgmsh-dev python3-matplotlib python3-numpy
      python3-vtk9)
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "installing: ${missing[*]}"
  sudo_cmd=""
  [ "$(id -u)" -eq 0 ] || sudo_cmd="sudo"
  $sudo_cmd apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
