# Our renderer's shaders: visibility, path tracing and gradient-sample passes. Tracing shaders come
# in two variants: ray queries, and the software BVH for devices without them.
asvgf_add_shader(gbuffer SOURCE renderer/gbuffer.comp
                 VARIANTS rayquery=TRACE_RAY_QUERY software=TRACE_SOFTWARE)
# The _split variants write diffuse and specular signals apart (scenes with glossy materials); the
# _full_range ones write fp32 illumination, for the methods that do not filter it (raw, reference);
# the _carried ones also shade A-SVGF's carried gradient samples (one invocation a 3x3 stratum,
# in workgroups past the image's rows), the _carried_only ones only those (beside the split ones).
asvgf_add_shader(pathtrace SOURCE renderer/pathtrace.comp
                 VARIANTS rayquery=TRACE_RAY_QUERY software=TRACE_SOFTWARE
                          rayquery_full_range=TRACE_RAY_QUERY,FULL_RANGE
                          software_full_range=TRACE_SOFTWARE,FULL_RANGE
                          rayquery_split=TRACE_RAY_QUERY,SPLIT_SPECULAR
                          software_split=TRACE_SOFTWARE,SPLIT_SPECULAR
                          rayquery_carried=TRACE_RAY_QUERY,CARRIED_SAMPLES
                          software_carried=TRACE_SOFTWARE,CARRIED_SAMPLES
                          rayquery_carried_only=TRACE_RAY_QUERY,CARRIED_SAMPLES,CARRIED_ONLY
                          software_carried_only=TRACE_SOFTWARE,CARRIED_SAMPLES,CARRIED_ONLY)
asvgf_add_shader(gradient_clear SOURCE renderer/gradient_clear.comp)
asvgf_add_shader(gradient_select SOURCE renderer/gradient_select.comp)
asvgf_add_shader(gradient_resolve SOURCE renderer/gradient_resolve.comp)
asvgf_add_shader(accumulate SOURCE renderer/accumulate.comp)
asvgf_add_shader(debug_view SOURCE renderer/debug_view.comp)
asvgf_add_shader(specular_motion SOURCE renderer/specular_motion.comp)
# Not a frame pass: the benchmark's bandwidth measurement.
asvgf_add_shader(bandwidth_copy SOURCE renderer/bandwidth_copy.comp)
asvgf_add_shader(export_aovs SOURCE renderer/export_aovs.comp)
asvgf_add_shader(widen_image SOURCE renderer/widen_image.comp VARIANTS floats halves=SOURCE_HALVES)
# Not a frame pass: the benchmark's cache probe (`--cache-latency`): buffer loads and image loads.
asvgf_add_shader(cache_latency SOURCE renderer/cache_latency.comp VARIANTS buffer image=CHASE_IMAGE)
