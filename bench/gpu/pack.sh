#!/usr/bin/env bash
# Packs what run.sh needs on a GPU machine that has no browser and no network, into three folders
# of the current directory (the root of the tree that is copied there; keep them out of git with
# `printf '/.gpu1/\n/.gpu2/\n/.gl/\n' >> .git/info/exclude`):
#   .gpu1  the Chromium headless shell, xz-compressed (about 54 MiB)
#   .gpu2  its data files and libraries, one font, and the built site with bench/gpu/gpu.html
#   .gl    Debian's GL, EGL and Vulkan loader packages
# Each folder stays under the 64 MiB one copy may carry. Needs Debian's apt (`apt-get update`
# once) and the project's node_modules; about 5 minutes on 2 cores, most of it xz.
set -euo pipefail
project=$(cd "$(dirname "$0")/../.." && pwd)
dest=$PWD
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$dest/.gpu1" "$dest/.gpu2" "$dest/.gl"

(cd "$work" && apt-get download chromium-headless-shell chromium-common >/dev/null)
(cd "$dest/.gl" && apt-get download libvulkan1 libegl1 libglvnd0 libopengl0 libgl1 libglx0 libgles2 >/dev/null)
mkdir -p "$work/x"
for deb in "$work"/*.deb; do dpkg -x "$deb" "$work/x"; done
shell_dir=$work/x/usr/lib/chromium
mkdir -p "$work/p/chrome" "$work/p/lib"
cp "$shell_dir"/{icudtl.dat,headless_lib_data.pak,headless_lib_strings.pak,headless_command_resources.pak} "$work/p/chrome/"
cp "$shell_dir"/{v8_context_snapshot.bin,snapshot_blob.bin,libEGL.so,libGLESv2.so,libvulkan.so.1} "$work/p/chrome/"
# The shell's libraries, but the C and C++ run-times the GPU machine has already.
for lib in $(ldd "$shell_dir/chromium-headless-shell" | awk '$3 ~ /^\// {print $3}'); do
  case "$(basename "$lib")" in
    libc.so.*|libm.so.*|libpthread.so.*|libstdc++.so.*|libgcc_s.so.*|ld-linux*) ;;
    *) cp -L "$lib" "$work/p/lib/" ;;
  esac
done
(cd "$work/p" && tar cf - chrome lib | xz -T0 -9 > "$dest/.gpu2/rest.tar.xz")
xz -T0 -9 -c "$shell_dir/chromium-headless-shell" > "$dest/.gpu1/hs.xz"
# The shell's font manager needs one font to start.
mkdir -p "$work/fonts/fonts"
cp /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf "$work/fonts/fonts/"
(cd "$work/fonts" && tar cJf "$dest/.gpu2/fonts.tar.xz" fonts)
(cd "$project" && FRESNEL_LAB_BENCH_PEER=1 npx vite build --outDir "$work/site" --emptyOutDir --logLevel warn)
(cd "$work" && tar cf - site | xz -T0 -6 > "$dest/.gpu2/site.tar.xz")
# run.sh travels in both parts: whichever copy arrives first can start the machine's side.
cp "$project/bench/gpu/run.sh" "$dest/.gpu1/run.sh"
cp "$project/bench/gpu/run.sh" "$dest/.gpu2/run.sh"
cp "$project/bench/gpu/collect.py" "$dest/.gpu2/collect.py"
du -sh "$dest/.gpu1" "$dest/.gpu2" "$dest/.gl"
