#!/usr/bin/env bash
# Installs everything the project needs on Debian 12 (bookworm). Idempotent and non-interactive:
# run as root; a second run installs nothing and takes seconds.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
export DEBIAN_FRONTEND=noninteractive

if [ "$(id -u)" -ne 0 ]; then
  echo "bootstrap: run as root (it installs Debian packages)" >&2
  exit 1
fi

# Debian packages from bookworm.
packages=(
  build-essential cmake ninja-build pkg-config git clang-format
  libvulkan-dev vulkan-tools vulkan-validationlayers
  libepoxy-dev libegl-dev
  glslang-tools glslang-dev spirv-tools spirv-cross libspirv-cross-c-shared-dev spirv-headers
  libglfw3-dev libglm-dev doctest-dev libstb-dev libtinyobjloader-dev libtinygltf-dev
  libtinyexr-dev nlohmann-json3-dev libcli11-dev
  xvfb xauth
  clang libclang-rt-14-dev  # tools/fuzz.sh: libFuzzer with ASan and UBSan
)
# Node.js and npm only when the machine has none (the WGSL step runs naga and Dawn in Node).
command -v node >/dev/null 2>&1 || packages+=(nodejs)
command -v npm >/dev/null 2>&1 || packages+=(npm)

# Mesa 25 from bookworm-backports: its lavapipe exposes VK_KHR_ray_query, bookworm's Mesa 22 does not.
backports_list=/etc/apt/sources.list.d/bookworm-backports.sources
need_update=0
if ! grep -rqs 'bookworm-backports' /etc/apt/sources.list /etc/apt/sources.list.d/; then
  cat >"$backports_list" <<'SRC'
Types: deb
URIs: http://deb.debian.org/debian
Suites: bookworm-backports
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
SRC
  need_update=1
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
# Mesa's Vulkan (lavapipe) and its GL/EGL drivers (llvmpipe, surfaceless EGL), all from backports.
mesa_packages=(mesa-vulkan-drivers libgl1-mesa-dri libegl-mesa0)
need_mesa=0
for p in "${mesa_packages[@]}"; do
  case "$(dpkg-query -W -f='${Version}' "$p" 2>/dev/null || true)" in *bpo*) ;; *) need_mesa=1 ;; esac
done

if [ ${#missing[@]} -gt 0 ] || [ $need_mesa -eq 1 ]; then
  if [ $need_update -eq 1 ] || [ ! -d /var/lib/apt/lists ] || [ -z "$(ls /var/lib/apt/lists/*backports* 2>/dev/null)" ]; then
    apt-get update -q
  fi
  if [ ${#missing[@]} -gt 0 ]; then
    echo "bootstrap: installing ${missing[*]}"
    apt-get install -y -q --no-install-recommends "${missing[@]}"
  fi
  if [ $need_mesa -eq 1 ]; then
    echo "bootstrap: installing ${mesa_packages[*]} from bookworm-backports"
    apt-get install -y -q --no-install-recommends -t bookworm-backports "${mesa_packages[@]}"
  fi
else
  echo "bootstrap: Debian packages already installed"
fi

# Pinned npm packages for the WGSL step (naga-wasm, webgpu), from the lockfile.
if [ -f "$here/package-lock.json" ]; then
  if ! cmp -s "$here/package-lock.json" "$here/node_modules/.package-lock.json" 2>/dev/null; then
    echo "bootstrap: npm ci in tools/"
    (cd "$here" && npm ci --no-audit --no-fund --loglevel=error)
  else
    echo "bootstrap: npm packages already installed"
  fi
fi

# The check that matters: a Vulkan device with ray queries must be visible.
if ! command -v vulkaninfo >/dev/null 2>&1; then
  echo "bootstrap: vulkaninfo is missing; the vulkan-tools package did not install" >&2
  exit 1
fi
summary="$(vulkaninfo --summary 2>&1 || true)"
if ! grep -q 'deviceName' <<<"$summary"; then
  echo "bootstrap: no Vulkan device is visible. vulkaninfo said:" >&2
  echo "$summary" | tail -n 20 >&2
  exit 1
fi
full="$(vulkaninfo 2>/dev/null || true)"
if ! grep -q 'VK_KHR_ray_query' <<<"$full"; then
  echo "bootstrap: a Vulkan device is visible but none offers VK_KHR_ray_query." >&2
  echo "  lavapipe needs Mesa >= 23 (installed mesa-vulkan-drivers: $(dpkg-query -W -f='${Version}' mesa-vulkan-drivers 2>/dev/null || echo none))." >&2
  exit 1
fi
echo "bootstrap: ok: $(grep -m1 'deviceName' <<<"$summary" | sed 's/.*= //') offers VK_KHR_ray_query"
