#!/usr/bin/env bash
# The GPU machine's side of the real-GPU check (README.md beside it), in two phases because one
# copy to that machine carries at most 64 MiB and the machine keeps /tmp between them:
#   bash .gpu1/run.sh stage   keeps the shell binary (.gpu1) in /tmp/stage and names the machine
#   bash .gpu2/run.sh run     unpacks .gpu2, finds an ANGLE back end that reaches the GPU, runs
#                             bench/gpu/gpu.html, and writes gpu.log and gpu.json to $OUT
# Environment: SIZE (normal | tiny), STEPS (gpu.html's steps), WAIT_S (how long to wait for the
# end), MODE_IDS (which back ends to try, by index), ACCEPT (a regular expression the renderer must
# match; nvidia by default).
set -u
stage=/tmp/stage
OUT=${OUT:-/tmp/out}
mkdir -p "$stage" "$OUT"
for part in .gpu1 .gpu2; do [ -d "$part" ] && cp -n "$part"/* "$stage"/ 2>/dev/null; done
for deb in .gl/*.deb; do [ -f "$deb" ] && dpkg -x "$deb" /; done
ldconfig
echo "== machine"; nvidia-smi -L 2>&1 | head -2; ldd --version | head -1; nproc
[ "${1:-}" = stage ] && { ls -la "$stage"; exit 0; }
[ -f "$stage/hs.xz" ] || { echo "part 1 is missing (a fresh machine: run the stage phase first)"; exit 3; }
cd "$stage"
if [ ! -x chrome/chromium-headless-shell ]; then
  tar xJf rest.tar.xz && tar xJf site.tar.xz && tar xJf fonts.tar.xz
  xz -dc hs.xz > chrome/chromium-headless-shell && chmod +x chrome/chromium-headless-shell
fi
export LD_LIBRARY_PATH=$stage/chrome:$stage/lib
mkdir -p "$stage/fccache"
printf '<?xml version="1.0"?><!DOCTYPE fontconfig SYSTEM "fonts.dtd"><fontconfig><dir>%s/fonts</dir><cachedir>%s/fccache</cachedir></fontconfig>' \
  "$stage" "$stage" > "$stage/fonts.conf"
export FONTCONFIG_FILE=$stage/fonts.conf
# The driver's own loader files, where NVIDIA's container runtime puts them.
icd=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
[ -f "$icd" ] && export VK_DRIVER_FILES=$icd VK_ICD_FILENAMES=$icd
egl=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
[ -f "$egl" ] && export __EGL_VENDOR_LIBRARY_FILENAMES=$egl
echo "== libraries not found"; ldd chrome/chromium-headless-shell | grep 'not found'
python3 -m http.server 8765 --bind 127.0.0.1 --directory "$stage/site" >/dev/null 2>&1 &
server=$!
sleep 1
shell="chrome/chromium-headless-shell --no-sandbox --disable-gpu-sandbox --enable-logging=stderr --v=0 --ignore-gpu-blocklist --no-first-run"
vulkan="--use-angle=vulkan --enable-features=Vulkan,VulkanFromANGLE,DefaultANGLEVulkan"
modes=("$vulkan" "--use-gl=angle $vulkan --disable-vulkan-surface" "--use-angle=gl-egl" "--use-gl=egl" "--use-angle=gl" ${EXTRA_MODE:+"$EXTRA_MODE"})
page=http://127.0.0.1:8765/bench/gpu/gpu.html
chosen=""
for i in ${MODE_IDS:-${!modes[@]}}; do
  timeout 60 $shell ${modes[$i]} --dump-dom --timeout=15000 "$page?steps=probe" > /dev/null 2> "$OUT/probe$i.log"
  renderer=$(grep -a -o '"renderer":"[^"]*' "$OUT/probe$i.log" | head -1 | sed 's/.*:"//')
  echo "mode $i [${modes[$i]}]: ${renderer:-no renderer}"
  if [ -z "$chosen" ] && echo "$renderer" | grep -qiE "${ACCEPT:-nvidia}"; then chosen=${modes[$i]}; fi
done
if [ -z "$chosen" ]; then
  echo "no back end reached the GPU"; grep -a -i 'error\|fail' "$OUT/probe0.log" | head -20; kill $server; exit 4
fi
echo "== gpu.html with [$chosen]"
$shell $chosen --disable-frame-rate-limit --disable-gpu-vsync --window-size=1600,1000 \
  "$page?size=${SIZE:-normal}&steps=${STEPS:-}" > /dev/null 2> "$OUT/gpu.log" &
browser=$!
for _ in $(seq 1 "${WAIT_S:-480}"); do
  sleep 1
  grep -aq 'GPUH DONE' "$OUT/gpu.log" && break
  kill -0 $browser 2>/dev/null || { echo "the shell exited"; break; }
done
kill $browser $server 2>/dev/null
python3 "$stage/collect.py" "$OUT/gpu.log" "$OUT/gpu.json"
grep -aq 'GPUH DONE' "$OUT/gpu.log" && echo "DONE" || echo "not done within the wait"
