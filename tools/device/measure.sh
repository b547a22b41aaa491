#!/usr/bin/env bash
# The measurements issues 36, 37 and 39 need on the H200, in one device call (prepare.sh first):
#   bash tools/device/measure.sh [bench] [glossy] [glossy-maps] [static] [light-exit] [orbit] [sigma] [local-mean] [local-mean-report]
#                                [local-mean-cost] [local-mean-default]
#                                [gl-composite] [vk-occupancy] [atrous] [atrous-quality] [glossy-probe] [ab] [iterations]
# (no step: bench glossy static). Each step has a time limit and its results go to
# $OUT/reports.tgz as soon as it ends, so that a run cut short still returns what it measured.
#   bench       asvgf bench at 1080p: Vulkan (ASVGF_VK_PIPELINE_STATS), OpenGL (ASVGF_GL_PROGRAM_DUMP), ES
#   glossy      report glossy/boxes-move, 12 frames: the specular split's settings (issue 39)
#   glossy-maps report glossy/boxes-move (and $GLOSSY_MAPS_ANIMATIONS), 12 frames: where the glossy error lies
#   static      report the static animation, 12 frames: energy bias by sigma_l, history tap and --local-mean
#   light-exit  the headline, 24 frames, K from plain accumulation at 128, 256 and 512 spp (about 4 minutes)
#   orbit       report glossy/orbit, 12 frames: the split against one signal with a moving camera
#   sigma       σ_l around the size rule's 12 at 1080p (issue 39): static and light-exit (energy), the
#               other built-in scenes, orbit and boxes-move (error), 12 frames each
#   local-mean  the energy probe (issue 39): static, 12 frames, the displayed frame's local mean corrected
#               to the temporal result's for k in $LOCAL_MEAN_K (default 9 17 33 65 129), with and without the gate
#   local-mean-report  the built correction (--local-mean 17, 33, 65; 33 with tap -1) in
#               `asvgf report` on light-exit and orbit (flicker, lag, energy), and its passes' time
#   local-mean-cost  the correction's passes at 1080p (k 65, 33, 17) on every backend and at 4K (k 129)
#   local-mean-default  the default (the correction on, k by size) against --local-mean 0: the bench twice
#               each, alternately, Vulkan and OpenGL, 1080p and 4K, then light-exit at 1080p (12 frames)
#   gl-composite  OpenGL's last a-trous iteration with the composite's stores or its pow edited out
#   vk-occupancy  Vulkan's path tracer with do-nothing shared memory (tools/device/occupancy_probe.sh
#               first; every .devbin/asvgf_vkpad<WORDS> it built)
#   resident    the path tracer's resident workgroups, counted (tools/device/resident_probe.sh first:
#               .devbin/asvgf_resident), on every backend, cornell and many; divide by the SMs
#   cache       asvgf bench --cache-latency on every backend: where each kind of load's cache ends
#   gaps        every pass timed from the previous pass's end (tools/device/timer_gaps_probe.sh first:
#               .devbin/asvgf_gaps) against the normal timers, Vulkan and OpenGL, 1080p and 480x270
#   bvh         path tracing with the BVH builder's leaf rules changed (tools/device/bvh_probe.sh first:
#               every .devbin/asvgf_bvh<LEAF>x<CAP>) against this build: cornell, textured, many; Vulkan, OpenGL
#   atrous      this build against every .devbin/asvgf_atrous_* (stripped probe binaries, built first):
#               the bench twice each, alternately, Vulkan 1080p; then OpenGL 1080p and Vulkan 4K once
#   atrous-quality  `asvgf report` at 1080p, light-exit (or $ATROUS_QUALITY_ANIMATIONS), 24 frames as the
#               issue's rule (or $ATROUS_QUALITY_FRAMES), seed 0 (or each of $ATROUS_QUALITY_SEEDS: the lag
#               can flip with the seed) and each frame's relMSE, for this build and every
#               .devbin/asvgf_atrous_* (the issue-36 quality check of the atrous step's probes)
#   glossy-probe  report glossy/boxes-move and glossy/orbit (or $GLOSSY_PROBE_ANIMATIONS), 12 frames, one
#               signal and the split, for this build and every .devbin/asvgf_glossy_* (build_probes.sh glossy)
#   iterations  5 a-trous iterations (the default) against 4 and 3: the bench (Vulkan and OpenGL 1080p,
#               Vulkan 4K) and the quality at 1080p (light-exit with two seeds, glossy boxes-move and orbit)
#   ab          this build against another (.devbin/asvgf_base: `cp` a stripped binary of the commit
#               before there; or several, oldest first: AB_BASES="asvgf_7b asvgf_base" names
#               .devbin/asvgf_7b and .devbin/asvgf_base): the bench twice each, alternately, on each backend in $AB_BACKENDS
#               (default vulkan; e.g. "vulkan gl"; none with AB_NO_BENCH=1), Vulkan at 4K once each with
#               AB_4K=1, then (unless AB_NO_QUALITY=1) the issue-36 quality check,
#               `asvgf report` at 1080p on light-exit (24 frames, asvgf) with each
set -uo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../.."
if command -v nvidia-smi >/dev/null; then  # the device's image has no Vulkan/GL loader; never here
  for deb in .gl/*.deb; do dpkg -x "$deb" /; done
  ldconfig
  nvidia-smi --query-gpu=name,driver_version,clocks.max.sm --format=csv,noheader
fi
export LD_LIBRARY_PATH=$PWD/.devbin/lib
A=./.devbin/asvgf
if ! $A info >/dev/null 2>&1; then  # the image's loaders look for the ICD where NVIDIA's container puts it
  export VK_DRIVER_FILES=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
  export __EGL_VENDOR_LIBRARY_FILENAMES=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
fi
R=/tmp/rep
mkdir -p $R
save() { (cd /tmp && tar czf "${OUT:-/tmp}/reports.tgz" rep); }
# MEASURE_SIZE and MEASURE_SPP shrink the runs for a dry run on lavapipe (e.g. 32x32 and 16).
size=${MEASURE_SIZE:-1920x1080}
BENCH=(--size "$size" --warmup 100 --frames 50 --time-step 0.02 --first-frame 4 --method asvgf)
HD=(--size "$size" --reference-spp "${MEASURE_SPP:-4096}")
steps=("$@")
[ ${#steps[@]} -gt 0 ] || steps=(bench glossy static)
for step in "${steps[@]}"; do
  echo "== $step $(date +%T)"
  case $step in
    bench)
      { echo "-- vulkan"; ASVGF_VK_PIPELINE_STATS=$R/vkstats timeout 60 $A bench "${BENCH[@]}"
        echo "-- gl"; ASVGF_GL_PROGRAM_DUMP=$R/gldump timeout 60 $A bench "${BENCH[@]}" --backend gl
        echo "-- gles"; timeout 60 $A bench "${BENCH[@]}" --backend gles; } > $R/bench.txt 2>&1
      grep -E "^--|^(denoiser|frame|pathtrace|gbuffer|temporal|atrous|copy)" $R/bench.txt
      for f in $R/vkstats/pathtrace.software.txt $R/vkstats/gbuffer.software.txt; do
        [ -f "$f" ] && { echo "-- $f"; grep -v "^ *representation\|^$" "$f" | head -14; }
      done ;;
    glossy)
      timeout 150 $A report --scene glossy --animation boxes-move "${HD[@]}" --frames 12 --methods svgf \
        --run def=asvgf --run 'split=asvgf --specular-split' \
        --run 'split-sl16=asvgf --specular-split --specular-sigma-l 16' \
        --run 'split-sl32=asvgf --specular-split --specular-sigma-l 32' \
        --run 'split-sl64=asvgf --specular-split --specular-sigma-l 64' \
        --run 'split-sl4=asvgf --specular-split --specular-sigma-l 4' \
        --run 'split-i5=asvgf --specular-split --specular-atrous-iterations 5' \
        --run 'split-sl32-i5=asvgf --specular-split --specular-sigma-l 32 --specular-atrous-iterations 5' \
        --run 'split-a10=asvgf --specular-split --specular-alpha 0.1' \
        --run 'tap-1=asvgf --history-tap -1' --run 'split-t=asvgf --specular-split --history-tap -1' \
        --out $R/glossy-boxes --quiet 2>&1 | tail -3 ;;
    glossy-maps)
      # Issue 39: where the glossy pixels' error lies at 1080p (the report's error_maps.png): one
      # signal, the split, the split with specular sigma_l 32; boxes-move (still camera) unless
      # GLOSSY_MAPS_ANIMATIONS names others (e.g. "boxes-move orbit").
      for anim in ${GLOSSY_MAPS_ANIMATIONS:-boxes-move}; do
        timeout 240 $A report --scene glossy --animation $anim "${HD[@]}" --frames 12 --methods raw,asvgf \
          --run 'split=asvgf --specular-split' --run 'split-sl32=asvgf --specular-split --specular-sigma-l 32' \
          --out $R/glossy-maps-$anim --quiet 2>&1 | tail -2
        save
      done ;;
    static)
      timeout 180 $A report "${HD[@]}" --animation static --frames 12 --methods raw --run def=asvgf \
        --run 'tap-1=asvgf --history-tap -1' --run 'sl4=asvgf --sigma-l 4' --run 'sl8=asvgf --sigma-l 8' \
        --run 'lm33=asvgf --local-mean 33' --run 'lm65=asvgf --local-mean 65' \
        --out $R/static --quiet 2>&1 | tail -3 ;;
    light-exit)
      timeout 300 $A report "${HD[@]}" --max-accumulation-spp 512 --methods accum-128spp,accum-256spp,accum-512spp \
        --run def=asvgf --run 'sl8=asvgf --sigma-l 8' --out $R/light-exit --quiet 2>&1 | tail -3 ;;
    orbit)
      timeout 150 $A report --scene glossy --animation orbit "${HD[@]}" --frames 12 --methods svgf \
        --run def=asvgf --run 'split=asvgf --specular-split' \
        --run 'split-sl16=asvgf --specular-split --specular-sigma-l 16' \
        --run 'split-sl32=asvgf --specular-split --specular-sigma-l 32' \
        --out $R/glossy-orbit --quiet 2>&1 | tail -3 ;;
    sigma)
      SL=(--run def=asvgf --run 'sl8=asvgf --sigma-l 8' --run 'sl16=asvgf --sigma-l 16')
      timeout 60 $A report "${HD[@]}" --animation static --frames 12 --methods raw "${SL[@]}" \
        --run 'sl24=asvgf --sigma-l 24' --run 'def-t=asvgf --history-tap -1' \
        --out $R/sigma-static --quiet 2>&1 | tail -1
      save
      timeout 200 $A report "${HD[@]}" --scenes cornell,glossy,textured --frames 12 --methods raw "${SL[@]}" \
        --out $R/sigma-scenes --quiet 2>&1 | tail -1
      save
      for anim in orbit boxes-move; do
        timeout 100 $A report --scene glossy --animation $anim "${HD[@]}" --frames 12 --methods raw \
          "${SL[@]}" --out $R/sigma-$anim --quiet 2>&1 | tail -1
        save
      done ;;
    local-mean)
      # docs/quality.md, "Energy: a correction of the displayed frame's local mean": static, 12 frames,
      # one reference frame (the scene never changes), the correction for each k with and without
      # the gate, by tools/probes/local_mean.py (one process a frame). The frames stay in /tmp/lm.
      L=/tmp/lm; rm -rf $L; mkdir -p $L/ref $R/local-mean
      S=(--size "$size" --animation static)
      timeout 150 $A render "${S[@]}" --frames 1 --method reference --spp "${MEASURE_SPP:-4096}" --out $L/ref1 >> $R/local-mean/render.log 2>&1
      timeout 60 $A render "${S[@]}" --frames 12 --history-tap -1 --atrous-iterations 0 --out $L/T >> $R/local-mean/render.log 2>&1
      timeout 60 $A render "${S[@]}" --frames 12 --history-tap -1 --out $L/F >> $R/local-mean/render.log 2>&1
      timeout 60 $A render "${S[@]}" --frames 12 --out $L/D >> $R/local-mean/render.log 2>&1
      for i in $(seq 0 11); do ln -sf ../ref1/frame_0000.exr "$(printf "$L/ref/frame_%04d.exr" "$i")"; done
      ks=(${LOCAL_MEAN_K:-9 17 33 65 129})
      for i in $(seq 0 11); do
        timeout 300 python3 tools/probes/local_mean.py $L "$i" "${ks[@]}" &
        timeout 300 python3 tools/probes/local_mean.py $L "$i" "${ks[@]}" --gate &
      done
      wait
      for d in T F D $(for k in "${ks[@]}"; do echo C$k C${k}g; done); do
        ./.devbin/exr_compare "$L/ref/frame_%04d.exr" "$L/$d/frame_%04d.exr" 0 12 > $R/local-mean/$d.txt 2>&1
        awk -v d=$d '/^frame/{f=$2+0; sub(",","",$4); r+=$4; n++; e=$7; sub("[%,]+","",e); if (f>=5){s+=e; m++}}
          END{printf "%-6s mean relMSE %.5f  energy bias (frames 5-11) %+.2f%%\n", d, r/n, s/m}' $R/local-mean/$d.txt
      done | tee $R/local-mean/summary.txt ;;
    local-mean-report)
      # The built correction (--local-mean) at 1080p: error, flicker, lag and energy on light-exit and
      # orbit, 12 frames each, then its cost in the bench.
      LM=(--run 'lm17=asvgf --local-mean 17' --run 'lm33=asvgf --local-mean 33' --run 'lm65=asvgf --local-mean 65'
          --run 't=asvgf --history-tap -1' --run 'lm33-t=asvgf --history-tap -1 --local-mean 33')
      for anim in light-exit orbit; do
        timeout 200 $A report "${HD[@]}" --animation $anim --frames 12 --methods raw --run def=asvgf "${LM[@]}" \
          --out $R/local-mean-$anim --quiet 2>&1 | tail -1
        # The energy target's frames: light-exit's still frames 1-3 (the report's column counts
        # only the frames after the change), from report.csv's image means.
        python3 - $R/local-mean-$anim/report.csv <<'EOF_PY' | tee $R/local-mean-$anim/still-energy.txt
import csv, sys
rows = [r for r in csv.DictReader(open(sys.argv[1])) if r["frame"] in ("1", "2", "3")]
for run in dict.fromkeys(r["run"] for r in rows):
    bias = ["%+.2f%%" % (100 * (float(r["mean"]) / float(r["reference_mean"]) - 1)) for r in rows if r["run"] == run]
    print("%-8s energy bias on frames 1-3: %s" % (run, " / ".join(bias)))
EOF_PY
        save
      done
      timeout 60 $A bench "${BENCH[@]}" --local-mean 33 2>&1 | grep -E "^(atrous.5|local_mean|composite|denoiser|frame)" ;;
    local-mean-cost)
      # The correction's passes (block sums, box, apply; for the history and the displayed colour)
      # at 1080p for k 65, 33 and 17 on every backend, and at 4K for k 129 (docs/quality.md, "The box
      # over blocks").
      for k in 65 33 17; do
        for backend in vulkan gl gles; do
          echo "-- k $k $backend: $(timeout 60 $A bench "${BENCH[@]}" --local-mean $k --backend $backend 2>&1 |
            grep -E '^(local_mean[^ ]*|denoiser|frame) ' | awk '{printf "%s %s  ", $1, $2}')"
        done
      done | tee $R/local-mean-cost.txt
      [ -n "${MEASURE_SIZE:-}" ] && continue  # a dry run: no 4K on lavapipe
      echo "-- 4K k 129: $(timeout 60 $A bench "${BENCH[@]/#$size/3840x2160}" --local-mean 129 2>&1 |
        grep -E '^(local_mean[^ ]*|denoiser) ' | awk '{printf "%s %s  ", $1, $2}')" | tee -a $R/local-mean-cost.txt ;;
    local-mean-default)
      # issue 39: what the default's correction costs and gives (docs/quality.md, "The local mean by
      # the image's size"; docs/performance.md's 336.9 B a pixel).
      for sz in "$size" 3840x2160; do
        [ -n "${MEASURE_SIZE:-}" ] && [ $sz = 3840x2160 ] && continue  # a dry run: no 4K on lavapipe
        for backend in vulkan gl; do
          for round in 1 2; do
            for lm in -1 0; do
              echo "-- $sz $backend --local-mean $lm round $round: $(timeout 60 $A bench "${BENCH[@]/#$size/$sz}" \
                --backend $backend --local-mean $lm 2>&1 | grep -E '^(atrous[^ ]*|local_mean[^ ]*|composite|denoiser|frame) ' |
                awk '{printf "%s %s  ", $1, $2}')"
            done
          done
        done
      done | tee $R/local-mean-default.txt
      save
      timeout 300 $A report "${HD[@]}" --frames 12 --methods raw --run 'def=asvgf' --run 'off=asvgf --local-mean 0' \
        --out $R/local-mean-default --quiet 2>&1 | tail -1 ;;
    gl-composite)
      # issue 37: the composite's share of OpenGL's atrous.5+composite (1.29-1.38x Vulkan's where the
      # middle iterations are 1.13-1.16x): the dumped program timed as it is and with three edits
      # (ASVGF_GL_PROGRAM_SOURCE), without the display image's store, the HDR image's, the sRGB pow.
      G=/tmp/glc; rm -rf $G; mkdir -p $G/nodisplay $G/nohdr $G/nopow
      ASVGF_GL_PROGRAM_DUMP=$G/dump timeout 60 $A bench "${BENCH[@]}" --backend gl > /dev/null 2>&1
      S=$G/dump/atrous.last_composite.glsl
      sed -E '/imageStore\(display,/d' $S > $G/nodisplay/atrous.last_composite.glsl
      sed -E '/imageStore\(hdr,/d' $S > $G/nohdr/atrous.last_composite.glsl
      sed -E 's/pow\(([^,()]+), 0\.4166666[0-9]*\)/\1/' $S > $G/nopow/atrous.last_composite.glsl
      for round in 1 2; do
        echo "-- gl round $round"; timeout 60 $A bench "${BENCH[@]}" --backend gl 2>&1 | grep -E "^(atrous|denoiser)"
        for d in nodisplay nohdr nopow; do
          echo "-- gl $d ($(diff $S $G/$d/atrous.last_composite.glsl | grep -c '^<') lines edited) round $round"
          ASVGF_GL_PROGRAM_SOURCE=$G/$d timeout 60 $A bench "${BENCH[@]}" --backend gl 2>&1 | grep -E "^(atrous.5|denoiser)"
        done
        echo "-- vulkan round $round"; timeout 60 $A bench "${BENCH[@]}" 2>&1 | grep -E "^(atrous|denoiser)"
      done | tee $R/gl-composite.txt ;;
    vk-occupancy)
      # issue 37: Vulkan's path tracer with its workgroups a SM limited by do-nothing shared memory
      # (binaries from tools/device/occupancy_probe.sh): if it slows toward OpenGL's time, OpenGL's
      # register use is what holds its path tracer down (counted since: the `resident` step).
      for round in 1 2; do
        for bin in $A .devbin/asvgf_vkpad*; do
          echo "-- $bin round $round"; timeout 60 $bin bench "${BENCH[@]}" 2>&1 | grep -E "^(pathtrace|frame) "
        done
      done | tee $R/vk-occupancy.txt ;;
    resident)
      # issue 37: how many path-tracing workgroups each backend's compiled program keeps resident
      # (the most in a frame, every frame; OpenGL reports no registers). 132 SMs on the H100 and H200.
      P=./.devbin/asvgf_resident
      [ -x $P ] || { echo "measure.sh resident: $P missing (tools/device/resident_probe.sh)" >&2; exit 2; }
      for scene in cornell many; do
        for backend in vulkan gl gles; do
          echo "-- $scene $backend"
          timeout 60 $P bench "${BENCH[@]}" --scene $scene --backend $backend 2>&1 |
            grep -E "^resident|^pathtrace " | sort | uniq -c | sort -rn | head -3
        done
      done | tee $R/resident.txt ;;
    gaps)
      # issue 37's small passes: each pass timed from the previous pass's end (tools/device/
      # timer_gaps_probe.sh first: .devbin/asvgf_gaps), so that a barrier OpenGL applies inside the
      # next pass's region counts on both APIs; beside the normal timers, at 1080p and 480x270.
      P=./.devbin/asvgf_gaps
      [ -x $P ] || { echo "measure.sh gaps: $P missing (tools/device/timer_gaps_probe.sh)" >&2; exit 2; }
      for gsize in "$size" 480x270; do
        for bin in $A $P; do
          for backend in vulkan gl; do
            echo "-- $bin $gsize $backend"
            timeout 60 $bin bench "${BENCH[@]/#$size/$gsize}" --backend $backend 2>&1 |
              grep -E "^(gbuffer|pathtrace|gradient|temporal|atrous|denoiser|frame)[^ ]* " | awk '{print $1, $2}'
          done
        done
      done | tee $R/gaps.txt ;;
    bvh)
      # Small scenes gained from smaller leaves where `many` lost (docs/performance.md, "The BVH's leaves").
      for scene in cornell textured many; do
        for bin in $A .devbin/asvgf_bvh*; do
          for backend in vulkan gl; do
            echo "-- $bin $scene $backend: $(timeout 60 $bin bench "${BENCH[@]}" --scene $scene --backend $backend 2>&1 |
              grep -E '^(gbuffer|pathtrace|frame) ' | awk '{printf "%s %s  ", $1, $2}')"
          done
        done
      done | tee $R/bvh.txt ;;
    cache)
      for backend in vulkan gl gles; do
        echo "-- $backend"; timeout 120 $A bench "${BENCH[@]}" --backend $backend --cache-latency 2>&1 | sed -n '/^copy/p;/cache latency/,$p'
      done | tee $R/cache.txt ;;
    atrous)
      probes=(./.devbin/asvgf_atrous_*)
      [ -x "${probes[0]}" ] || { echo "measure.sh atrous: no .devbin/asvgf_atrous_*: build the probes first" >&2; exit 2; }
      bench() {
        echo "-- $1 $2 $3"
        timeout 60 "$1" bench "${BENCH[@]/$size/$3}" --backend "$2" 2>&1 | grep -E "^(atrous|local_mean|composite|denoiser|frame)|error"
      }
      for round in 1 2; do
        for bin in $A "${probes[@]}"; do bench "$bin" vulkan "$size"; done
      done | tee $R/atrous-vulkan.txt
      save
      for bin in $A "${probes[@]}"; do bench "$bin" gl "$size"; done | tee $R/atrous-gl.txt
      save
      for bin in $A "${probes[@]}"; do bench "$bin" vulkan "${MEASURE_SIZE_4K:-3840x2160}"; done | tee $R/atrous-4k.txt
      save ;;
    atrous-quality)
      # The issue-36 quality check for the atrous step's probes: `asvgf report` at 1080p (24 frames,
      # light-exit, or each of $ATROUS_QUALITY_ANIMATIONS, e.g. "light-exit static") with this build
      # and each .devbin/asvgf_atrous_*, raw beside it for the reference's noise.
      for bin in $A ./.devbin/asvgf_atrous_*; do
        for anim in ${ATROUS_QUALITY_ANIMATIONS:-light-exit}; do
          for seed in ${ATROUS_QUALITY_SEEDS:-0}; do
            out=$R/quality-$anim-seed$seed-$(basename $bin)
            timeout 240 $bin report "${HD[@]}" --animation $anim --frames ${ATROUS_QUALITY_FRAMES:-24} --seed $seed \
              --methods raw --run def=asvgf --out $out --quiet > /dev/null 2>&1 || echo "report failed: $out"
            echo "$(basename $bin) $anim seed $seed: $(grep -h '^| `def`' $out/report.md | head -1 | cut -c1-160)"
            echo "  per frame: $(grep '^def,' $out/report.csv | cut -d, -f9 | tr '\n' ' ')"
            save
          done
        done
      done ;;
    glossy-probe)
      # Issue 39: each glossy probe binary against this build, one signal and the split, with error maps.
      for bin in $A ./.devbin/asvgf_glossy_*; do
        for anim in ${GLOSSY_PROBE_ANIMATIONS:-boxes-move orbit}; do
          out=$R/glossy-probe-$anim-$(basename $bin)
          timeout 240 $bin report --scene glossy --animation $anim "${HD[@]}" --frames 12 --methods raw \
            --run def=asvgf --run 'split=asvgf --specular-split' --out $out --quiet 2>&1 | tail -1
          echo "$(basename $bin) $anim:"; grep -h '^| `\(def\|split\)`' $out/report.md | cut -c1-200
          save
        done
      done ;;
    ab)
      # The builds compared, oldest first: .devbin/asvgf_base, or each .devbin/<name> of $AB_BASES
      # (e.g. "asvgf_7b asvgf_base"), then this build.
      BASES=()
      for name in ${AB_BASES:-asvgf_base}; do
        [ -x ./.devbin/$name ] || { echo "measure.sh ab: ./.devbin/$name missing" >&2; exit 2; }
        BASES+=(./.devbin/$name)
      done
      for backend in ${AB_BACKENDS:-vulkan}; do
        [ -n "${AB_NO_BENCH:-}" ] && break
        for round in 1 2; do
          for bin in "${BASES[@]}" $A; do
            echo "-- $bin $backend round $round"
            timeout 60 $bin bench "${BENCH[@]}" --backend $backend 2>&1 |
              grep -E "^(gbuffer|pathtrace|gradient|temporal|atrous|local_mean|composite|denoiser|frame)"
          done
        done
      done | tee $R/ab-bench.txt
      save
      if [ -n "${AB_4K:-}" ] && [ -z "${AB_NO_BENCH:-}" ]; then  # Vulkan at 4K, once each (MEASURE_SIZE_4K for a dry run)
        for bin in "${BASES[@]}" $A; do
          echo "-- $bin vulkan ${MEASURE_SIZE_4K:-3840x2160}"
          timeout 90 $bin bench "${BENCH[@]/#$size/${MEASURE_SIZE_4K:-3840x2160}}" 2>&1 | grep -E "^(gradient|denoiser|frame)"
        done | tee $R/ab-4k.txt
        save
      fi
      [ -n "${AB_NO_QUALITY:-}" ] && continue
      for bin in "${BASES[@]}" $A; do
        timeout 200 $bin report "${HD[@]}" --methods asvgf --out $R/ab-$(basename $bin) --quiet 2>&1 | tail -1
        grep -h "^| \`asvgf\`" $R/ab-$(basename $bin)/report.md | head -1
        save
      done ;;
    iterations)
      # Issue 36's lead: 5 a-trous iterations (the default) against 4 and 3. The bench twice each,
      # alternately, Vulkan 1080p; OpenGL 1080p and Vulkan 4K once each; then the quality check at
      # 1080p: light-exit (24 frames, seeds 0 and 1: the lag can flip with the seed), glossy
      # boxes-move and orbit (12 frames).
      for round in 1 2; do
        for it in 5 4 3; do
          echo "-- vulkan it$it round $round"
          timeout 60 $A bench "${BENCH[@]}" --atrous-iterations $it 2>&1 | grep -E "^(atrous|denoiser|frame)"
        done
      done | tee $R/it-bench.txt
      for it in 5 4; do
        echo "-- gl it$it"
        timeout 60 $A bench "${BENCH[@]}" --atrous-iterations $it --backend gl 2>&1 | grep -E "^(denoiser|frame)"
        echo "-- vulkan 4K it$it"
        timeout 90 $A bench "${BENCH[@]/#$size/${MEASURE_SIZE_4K:-3840x2160}}" --atrous-iterations $it 2>&1 |
          grep -E "^(denoiser|frame)"
      done | tee -a $R/it-bench.txt
      save
      IT=(--methods raw --run def=asvgf --run 'it4=asvgf --atrous-iterations 4' --run 'it3=asvgf --atrous-iterations 3')
      for seed in 0 1; do
        timeout 200 $A report "${HD[@]}" "${IT[@]}" --seed $seed --out $R/it-light-exit-s$seed --quiet 2>&1 | tail -1
        save
      done
      for anim in boxes-move orbit; do
        timeout 150 $A report --scene glossy --animation $anim "${HD[@]}" --frames 12 "${IT[@]}" \
          --out $R/it-glossy-$anim --quiet 2>&1 | tail -1
        save
      done ;;
    *) echo "measure.sh: unknown step '$step'" >&2; exit 2 ;;
  esac
  save
done
# The reports' summary rows, where steps wrote reports (none is not a failure).
grep -h "^| \`" $R/*/report.md 2>/dev/null | cut -c1-170 | head -60 || true
