# `asvgf report` at a tiny size: every method with finite numbers, valid non-empty plots, the same
# numbers for the same seed, --methods restricting the runs. Output under the build tree.
set(report_dir ${CMAKE_CURRENT_BINARY_DIR}/report_tests)
set(report_check "python3 ${CMAKE_CURRENT_SOURCE_DIR}/report_check.py")
set(report_tiny --size 24x24 --frames 10 --reference-spp 32 --max-accumulation-spp 4 --quiet)
list(JOIN report_tiny " " report_tiny_args)
set(report_all_runs raw,ema-0.2,ema-0.05,svgf,asvgf,asvgf-reproj,asvgf-nodemod,asvgf-box9,asvgf-box15,accum-1spp,accum-2spp,accum-4spp)

asvgf_add_cli_test("asvgf report writes every method with finite numbers and valid PNG plots" LABEL app EXIT 0
                   MATCH "report_check: ok: 12 runs x 10 frames"
                   COMMAND bash -c "rm -rf ${report_dir}/all && $<TARGET_FILE:asvgf> report ${report_tiny_args} --out ${report_dir}/all && ${report_check} check ${report_dir}/all ${report_all_runs}")
asvgf_add_cli_test("asvgf report gives the same numbers for the same seed and others for another" LABEL app EXIT 0
                   MATCH "rows differ in relMSE"
                   COMMAND bash -c "rm -rf ${report_dir}/seed_a ${report_dir}/seed_b ${report_dir}/seed_c && $<TARGET_FILE:asvgf> report ${report_tiny_args} --seed 3 --out ${report_dir}/seed_a && $<TARGET_FILE:asvgf> report ${report_tiny_args} --seed 3 --out ${report_dir}/seed_b && $<TARGET_FILE:asvgf> report ${report_tiny_args} --seed 4 --methods asvgf,accum --out ${report_dir}/seed_c && ${report_check} same ${report_dir}/seed_a ${report_dir}/seed_b && ${report_check} differ ${report_dir}/seed_a ${report_dir}/seed_c")
# The same report on OpenGL 4.5 and on Vulkan (seed 3) against Vulkan with seed 4: the backend must
# move each error column's run means (summed over runs) less than another seed does. It moves them
# at all because the rays through the room's corner creases (4 pixels of 576 here) tie between two
# walls and GL's compiler rounds t differently (tests/gl/gbuffer_parity_test.cpp): those pixels
# take other paths, and the filters spread them a little. Measured ratios backend/seed on llvmpipe:
# relMSE 0.07, SSIM 0.27, temporal error 0.59 (it weighs the frames after the light left most).
asvgf_add_cli_test("asvgf report --backend gl gives Vulkan's numbers within seed noise" LABEL app EXIT 0
                   MATCH "report_check: ok: 12 runs within noise"
                   COMMAND bash -c "rm -rf ${report_dir}/backend_vk ${report_dir}/backend_gl ${report_dir}/backend_seed && $<TARGET_FILE:asvgf> report ${report_tiny_args} --seed 3 --out ${report_dir}/backend_vk && $<TARGET_FILE:asvgf> report ${report_tiny_args} --seed 3 --backend gl --out ${report_dir}/backend_gl && $<TARGET_FILE:asvgf> report ${report_tiny_args} --seed 4 --out ${report_dir}/backend_seed && ${report_check} noise ${report_dir}/backend_vk ${report_dir}/backend_gl ${report_dir}/backend_seed")
asvgf_add_cli_test("asvgf report --methods restricts the runs and says where the report landed" LABEL app EXIT 0
                   MATCH "report: [^ ]*report_tests/methods/report\\.md"
                   COMMAND bash -c "rm -rf ${report_dir}/methods && mkdir -p ${report_dir} && $<TARGET_FILE:asvgf> report --size 24x24 --frames 10 --reference-spp 32 --max-accumulation-spp 2 --methods asvgf,reference --out ${report_dir}/methods > ${report_dir}/methods.log 2>&1 && tail -n 3 ${report_dir}/methods.log && ${report_check} check ${report_dir}/methods asvgf,accum-1spp,accum-2spp")
asvgf_add_cli_test("asvgf report --timing separate times every frame in a back-to-back pass and says so" LABEL app EXIT 0
                   MATCH "rendered a second time for timing"
                   COMMAND bash -c "rm -rf ${report_dir}/timing && $<TARGET_FILE:asvgf> report ${report_tiny_args} --methods asvgf,accum --timing separate --out ${report_dir}/timing && ${report_check} check ${report_dir}/timing asvgf,accum-1spp,accum-4spp && ${report_check} timed ${report_dir}/timing && grep -o 'rendered a second time for timing' ${report_dir}/timing/report.md")
asvgf_add_cli_test("asvgf report --run --local-mean: the local-mean correction gives back energy the filter loses and lowers the error on the static room: its energy bias within two thirds of the uncorrected filter's, its relMSE lower; with the default history tap, whose history it corrects too, within a third; the default (k by the image's size, 5 here) within a third of --local-mean 0" LABEL app EXIT 0
                   MATCH "report_check: ok: energy bias off [^,]*, asvgf "
                   COMMAND bash -c "rm -rf ${report_dir}/local-mean && $<TARGET_FILE:asvgf> report --size 48x48 --frames 24 --reference-spp 64 --max-accumulation-spp 1 --quiet --animation static --methods asvgf --run 'off=asvgf --local-mean 0' --run 't=asvgf --history-tap -1 --local-mean 0' --run 'lm=asvgf --history-tap -1 --local-mean 5' --run 'lm0=asvgf --local-mean 5' --out ${report_dir}/local-mean && ${report_check} corrects-energy ${report_dir}/local-mean t lm && ${report_check} corrects-energy ${report_dir}/local-mean off lm0 0.3333 && ${report_check} corrects-energy ${report_dir}/local-mean off asvgf 0.3333")
asvgf_add_cli_test("asvgf report on the static room gives every run an energy bias (ema-0.05 saturates after 20 of 24 frames), as report.csv's means say" LABEL app EXIT 0
                   MATCH "report_check: ok: energy bias of 12 runs"
                   COMMAND bash -c "rm -rf ${report_dir}/energy && $<TARGET_FILE:asvgf> report --size 24x24 --frames 24 --reference-spp 32 --max-accumulation-spp 4 --quiet --animation static --out ${report_dir}/energy && ${report_check} energy ${report_dir}/energy")
asvgf_add_cli_test("asvgf report --scenes all reports every built-in scene and a summary table over them, --run's runs included whatever their name" LABEL app EXIT 0
                   MATCH "report_check: ok: 4 scenes x 5 runs in summary.csv, 12 table rows"
                   COMMAND bash -c "rm -rf ${report_dir}/scenes && $<TARGET_FILE:asvgf> report --scenes all --size 24x24 --frames 6 --reference-spp 16 --max-accumulation-spp 4 --methods raw,asvgf,accum --run 'own-box=asvgf --kernel box' --quiet --out ${report_dir}/scenes && ${report_check} scenes ${report_dir}/scenes cornell,glossy,textured,many raw,asvgf,own-box,accum-1spp,accum-4spp")
asvgf_add_cli_test("asvgf report --scenes rejects an unknown scene with exit 2, naming it and the valid ones" LABEL app EXIT 2
                   MATCH "--scenes.*'kitchen' is neither a built-in scene \\(cornell, glossy, textured, many"
                   COMMAND ${asvgf} report --scenes cornell,kitchen --out ${report_dir}/never)
asvgf_add_cli_test("asvgf report --scenes refuses two scenes that would share a report folder, exit 2" LABEL app EXIT 2
                   MATCH "--scenes.*would both write to cornell/"
                   COMMAND ${asvgf} report --scenes cornell,glossy,cornell --out ${report_dir}/never)
asvgf_add_cli_test("asvgf report --run adds runs of one's own settings: asvgf's defaults repeat asvgf's numbers, --sigma-l 8 changes them, --specular-split on the matte room is rendered as its twin" LABEL app EXIT 0
                   MATCH "ok: asvgf and own-sl8 differ"
                   COMMAND bash -c "rm -rf ${report_dir}/run && $<TARGET_FILE:asvgf> report --size 24x24 --frames 6 --reference-spp 16 --max-accumulation-spp 2 --quiet --methods asvgf,accum --run own-default=asvgf --run 'own-sl8=asvgf --sigma-l 8' --run 'own-split=asvgf --specular-split' --out ${report_dir}/run && ${report_check} check ${report_dir}/run asvgf,accum-1spp,accum-2spp,own-default,own-sl8,own-split && ${report_check} runs ${report_dir}/run asvgf own-default same && ${report_check} runs ${report_dir}/run asvgf own-split same && ${report_check} runs ${report_dir}/run asvgf own-sl8 differ")
asvgf_add_cli_test("asvgf report --run: --specular-sigma-l and --specular-alpha change the split's specular chain, equal the diffuse chain's values reproduce it, and without --specular-split they change nothing" LABEL app EXIT 0
                   MATCH "ok: split and split-a5 differ"
                   COMMAND bash -c "rm -rf ${report_dir}/specular && $<TARGET_FILE:asvgf> report --scene glossy --size 24x24 --frames 6 --reference-spp 16 --max-accumulation-spp 1 --quiet --methods asvgf --run 'split=asvgf --specular-split' --run 'split-sl4=asvgf --specular-split --specular-sigma-l 4 --specular-alpha 0.2' --run 'split-sl16=asvgf --specular-split --specular-sigma-l 16' --run 'split-a5=asvgf --specular-split --specular-alpha 0.05' --run 'one-sl16=asvgf --specular-sigma-l 16 --specular-alpha 0.05' --out ${report_dir}/specular && ${report_check} runs ${report_dir}/specular split split-sl4 same && ${report_check} runs ${report_dir}/specular asvgf one-sl16 same && ${report_check} runs ${report_dir}/specular split split-sl16 differ && ${report_check} runs ${report_dir}/specular split split-a5 differ")
asvgf_add_cli_test("asvgf report --run refuses a setting outside its range with exit 2, naming the run and the range" LABEL app EXIT 2
                   MATCH "--run: 'x=asvgf --alpha 2': --alpha: alpha \\(--alpha\\) is 2, valid: \\(0, 1"
                   COMMAND ${asvgf} report --methods raw --run "x=asvgf --alpha 2" --out ${report_dir}/never)
asvgf_add_cli_test("asvgf report --run refuses a name already in use with exit 2" LABEL app EXIT 2
                   MATCH "--run: 'svgf=asvgf': the name 'svgf' is already a run's"
                   COMMAND ${asvgf} report --methods raw --run svgf=asvgf --out ${report_dir}/never)
asvgf_add_cli_test("asvgf report rejects an unknown --methods entry with exit 2" LABEL app EXIT 2 MATCH "--methods.*magic"
                   COMMAND ${asvgf} report --methods asvgf,magic --out ${report_dir}/never)
asvgf_add_cli_test("asvgf report rejects an impossible size with exit 2" LABEL app EXIT 2 MATCH "size"
                   COMMAND ${asvgf} report --size 0x5 --out ${report_dir}/never)
