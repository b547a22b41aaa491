# asvgf-demo: command line, and under xvfb-run a scripted run compared with `asvgf render`, and
# resizes during a run with the validation layer on.
if(NOT TARGET asvgf-demo)
  return()
endif()

# Compares two PNGs channel by channel (stb_image from Debian's libstb, header only).
add_executable(demo_compare_png ${CMAKE_CURRENT_LIST_DIR}/demo_compare_png.cpp)
asvgf_warnings(demo_compare_png)

set(demo $<TARGET_FILE:asvgf-demo>)
asvgf_add_cli_test("asvgf-demo --help lists the options and the controls" LABEL app EXIT 0
                   MATCH "--frames.*--screenshot.*--resize-at.*PageUp.*right mouse drag.*1 2 3 4 5.*Esc"
                   COMMAND bash -c "$<TARGET_FILE:asvgf-demo> --help | tr '\\n' ' '")
asvgf_add_cli_test("asvgf-demo rejects a malformed --resize-at with exit 2" LABEL app EXIT 2 MATCH "--resize-at"
                   COMMAND ${demo} --resize-at 3 64by64)
asvgf_add_cli_test("asvgf-demo rejects an unknown --view with exit 2" LABEL app EXIT 2 MATCH "--view"
                   COMMAND ${demo} --view sideways)
asvgf_add_cli_test("asvgf-demo --backend gl with a malformed ASVGF_GL_SHADERS exits 2 before opening a window, naming it" LABEL app EXIT 2
                   MATCH "ASVGF_GL_SHADERS is 'bogus'; valid: glsl, spirv" ENV ASVGF_GL_SHADERS=bogus
                   COMMAND ${demo} --backend gl --frames 1)

find_program(ASVGF_XVFB_RUN xvfb-run)
if(NOT ASVGF_XVFB_RUN)
  message(STATUS "asvgf-demo: xvfb-run not found, the window tests are left out (tools/bootstrap.sh installs xvfb)")
  return()
endif()

# The screenshot of frame 29 must equal `asvgf render`'s frame_0029.png with the same scene,
# animation (orbit: the camera moves, so a wrong animation time shows), method, size and seed, to
# the bit: the frame is reproducible (A-SVGF's gradient samples are chosen by lowest bid, not by the
# order invocations run in), and the demo presents the same display image the CLI writes. A real
# divergence — frame 28 instead of 29, seed 8 instead of 7, svgf instead of asvgf — changes 47-83%
# of the pixels by up to 12-31 steps.
set(demo_shot ${CMAKE_CURRENT_BINARY_DIR}/demo_screenshot)
asvgf_add_cli_test("asvgf-demo --frames 30 --screenshot equals asvgf render frame 29 under validation" LABEL app EXIT 0
                   MATCH "validation messages: 0.*demo_compare_png: .*match"
                   COMMAND bash -c "set -o pipefail && ( rm -rf '${demo_shot}' && \
$<TARGET_FILE:asvgf> render --frames 30 --method asvgf --size 64x64 --animation orbit --seed 7 --out '${demo_shot}' --quiet && \
${ASVGF_XVFB_RUN} -a $<TARGET_FILE:asvgf-demo> --frames 30 --method asvgf --size 64x64 --animation orbit --seed 7 \
--validation --screenshot '${demo_shot}/demo.png' && \
$<TARGET_FILE:demo_compare_png> '${demo_shot}/frame_0029.png' '${demo_shot}/demo.png' 0 0 ) 2>&1 | tr '\\n' ' '")

# A resize in the middle of a run recreates the swapchain (render size kept, the blit scales), and
# with --fit-window also the renderer; the validation layer stays silent in both.
asvgf_add_cli_test("asvgf-demo resized at frame 4 recreates the swapchain with no validation message" LABEL app EXIT 0
                   MATCH "frame 4: window resized to 96x72 \\(framebuffer 96x72\\).*8 frames. swapchain created ([2-9]|[1-9][0-9]) times.*validation messages: 0"
                   COMMAND bash -c "set -o pipefail && ${ASVGF_XVFB_RUN} -a $<TARGET_FILE:asvgf-demo> --frames 8 --size 32x32 \
--method asvgf --animation light-exit --validation --resize-at 4 96x72 2>&1 | tr '\\n' ' '")
asvgf_add_cli_test("asvgf-demo --fit-window resized at frame 3 renders at the new size with no validation message" LABEL app EXIT 0
                   MATCH "frame 3: window resized to 48x40 \\(framebuffer 48x40\\).*6 frames. swapchain created ([2-9]|[1-9][0-9]) times.*48x40.*validation messages: 0"
                   COMMAND bash -c "set -o pipefail && ${ASVGF_XVFB_RUN} -a $<TARGET_FILE:asvgf-demo> --frames 6 --window 32x32 \
--fit-window --method svgf --validation --resize-at 3 48x40 2>&1 | tr '\\n' ' '")
# On the OpenGL backends the device adopts the window's context and the image is blitted into its
# back buffer: the screenshot equals `asvgf render --backend gl`'s frame to the bit, and resizes
# (with --fit-window the renderer too) keep GL's debug output silent.
set(demo_gl_shot ${CMAKE_CURRENT_BINARY_DIR}/demo_gl_screenshot)
asvgf_add_cli_test("asvgf-demo --backend gl and gles present through a GL window: frame 29 equals asvgf render --backend gl, resizes stay silent" LABEL app EXIT 0
                   MATCH "framebuffer at 1 sizes.*validation messages: 0.*demo_compare_png: .*match.*frame 3: window resized to 48x40.*6 frames. framebuffer at 2 sizes.*48x40.*validation messages: 0.*frame 4: window resized to 96x72.*framebuffer at 2 sizes.*validation messages: 0"
                   COMMAND bash -c "set -o pipefail && ( rm -rf '${demo_gl_shot}' && \
$<TARGET_FILE:asvgf> render --backend gl --frames 30 --method asvgf --size 64x64 --animation orbit --seed 7 --out '${demo_gl_shot}' --quiet && \
${ASVGF_XVFB_RUN} -a $<TARGET_FILE:asvgf-demo> --backend gl --frames 30 --method asvgf --size 64x64 --animation orbit --seed 7 \
--validation --screenshot '${demo_gl_shot}/demo.png' && \
$<TARGET_FILE:demo_compare_png> '${demo_gl_shot}/frame_0029.png' '${demo_gl_shot}/demo.png' 0 0 && \
${ASVGF_XVFB_RUN} -a $<TARGET_FILE:asvgf-demo> --backend gl --frames 6 --window 32x32 --fit-window --method svgf --validation --resize-at 3 48x40 && \
${ASVGF_XVFB_RUN} -a $<TARGET_FILE:asvgf-demo> --backend gles --frames 8 --size 32x32 --method asvgf --animation light-exit --validation --resize-at 4 96x72 \
) 2>&1 | tr '\\n' ' '")

# A resize storm: 50 resizes in 50 frames, each to a size the last frame did not have, with the
# renderer recreated each time too (--fit-window), and on OpenGL; every tenth frame is presented to
# a hidden (unmapped) window after a minimise/restore (which Xvfb, without a window manager,
# ignores); validation and GL debug output stay silent, and the swapchain (or GL framebuffer)
# follows every size.
asvgf_add_cli_test("asvgf-demo survives a storm of 50 resizes with no validation message, on Vulkan and OpenGL" LABEL app EXIT 0
                   MATCH "52 frames. swapchain created 50 times. presented hidden 5 times.*validation messages: 0.*52 frames. swapchain created 50 times. presented hidden 5 times.*40x56.*validation messages: 0.*52 frames. framebuffer at 50 sizes. presented hidden 5 times.*validation messages: 0"
                   COMMAND bash -c "set -o pipefail && ( \
${ASVGF_XVFB_RUN} -a $<TARGET_FILE:asvgf-demo> --frames 52 --size 32x32 --animation light-exit --validation --resize-storm 50 && \
${ASVGF_XVFB_RUN} -a $<TARGET_FILE:asvgf-demo> --frames 52 --window 32x32 --fit-window --method svgf --validation --resize-storm 50 && \
${ASVGF_XVFB_RUN} -a $<TARGET_FILE:asvgf-demo> --backend gl --frames 52 --size 32x32 --validation --resize-storm 50 \
) 2>&1 | grep -v 'window resized' | tr '\\n' ' '")

# The denoiser-state views (heat maps from debug_view.comp) on a frame where the box moves, so the
# gradient passes run, for each method that has the buffer.
asvgf_add_cli_test("asvgf-demo shows the gradient, alpha, variance and history views with no validation message" LABEL app EXIT 0
                   MATCH "view gradient.*validation messages: 0.*view alpha.*validation messages: 0.*view variance.*validation messages: 0.*view history.*validation messages: 0"
                   COMMAND bash -c "set -o pipefail && ( \
${ASVGF_XVFB_RUN} -a $<TARGET_FILE:asvgf-demo> --frames 6 --size 32x32 --animation boxes-move --validation --view gradient && \
${ASVGF_XVFB_RUN} -a $<TARGET_FILE:asvgf-demo> --frames 6 --size 32x32 --animation boxes-move --validation --view alpha --method svgf && \
${ASVGF_XVFB_RUN} -a $<TARGET_FILE:asvgf-demo> --frames 6 --size 32x32 --animation boxes-move --validation --view variance --method ema && \
${ASVGF_XVFB_RUN} -a $<TARGET_FILE:asvgf-demo> --frames 6 --size 32x32 --animation boxes-move --validation --view history \
) 2>&1 | tr '\\n' ' '")
set_tests_properties("app: asvgf-demo survives a storm of 50 resizes with no validation message, on Vulkan and OpenGL"
                     "app: asvgf-demo --backend gl and gles present through a GL window: frame 29 equals asvgf render --backend gl, resizes stay silent"
                     "app: asvgf-demo shows the gradient, alpha, variance and history views with no validation message"
                     "app: asvgf-demo --frames 30 --screenshot equals asvgf render frame 29 under validation"
                     "app: asvgf-demo resized at frame 4 recreates the swapchain with no validation message"
                     "app: asvgf-demo --fit-window resized at frame 3 renders at the new size with no validation message"
                     PROPERTIES TIMEOUT 600 RUN_SERIAL TRUE)
