# Denoiser passes (A-SVGF on SVGF); included by shaders/CMakeLists.txt.
# gradient: `in_illumination` reads the re-shaded sample's luminance from its pixel, `given` from the
# gradient sample's z (DenoiserConfig::gradient_current_given).
asvgf_add_shader(gradient SOURCE denoise/gradient.comp VARIANTS in_illumination given=CURRENT_GIVEN)
# gradient_atrous: `first` writes the strata guide the `rest` read; the `samples` ones compute the
# gradient from the samples (the first iteration, l_cur given).
asvgf_add_shader(gradient_atrous SOURCE denoise/gradient_atrous.comp
                 VARIANTS plain first=GUIDE_OUT rest=GUIDE_IN samples=SAMPLES_IN samples_first=SAMPLES_IN,GUIDE_OUT)
# temporal: the `rgb9e5` ones are a spatial chain's (its colour history and result as RGB9E5 words).
asvgf_add_shader(temporal SOURCE denoise/temporal.comp
                 VARIANTS constant adaptive=ADAPTIVE constant_virtual=VIRTUAL_MOTION adaptive_virtual=ADAPTIVE,VIRTUAL_MOTION
                          constant_halves=MOTION_HALVES adaptive_halves=ADAPTIVE,MOTION_HALVES
                          constant_rgb9e5=COLOR_RGB9E5 adaptive_rgb9e5=ADAPTIVE,COLOR_RGB9E5
                          constant_rgb9e5_halves=COLOR_RGB9E5,MOTION_HALVES
                          adaptive_rgb9e5_halves=ADAPTIVE,COLOR_RGB9E5,MOTION_HALVES
                          constant_virtual_rgb9e5=VIRTUAL_MOTION,COLOR_RGB9E5
                          adaptive_virtual_rgb9e5=ADAPTIVE,VIRTUAL_MOTION,COLOR_RGB9E5)
# variance, atrous (the first packed iteration and the composite-folding ones), composite: the
# `albedo_rgb9e5` ones read the albedo as RGB9E5 words (R32UI, common/albedo.glsl), the others as floats.
asvgf_add_shader(variance SOURCE denoise/variance.comp VARIANTS plain albedo_rgb9e5=ALBEDO_RGB9E5)
asvgf_add_shader(atrous SOURCE denoise/atrous.comp
                 VARIANTS plain history=HISTORY
                          first=PACKED_OUT first_history=PACKED_OUT,HISTORY
                          first_sums=PACKED_OUT,LOCAL_MEAN_SUMS first_history_sums=PACKED_OUT,HISTORY,LOCAL_MEAN_SUMS
                          first_albedo_rgb9e5=PACKED_OUT,ALBEDO_RGB9E5
                          first_history_albedo_rgb9e5=PACKED_OUT,HISTORY,ALBEDO_RGB9E5
                          first_sums_albedo_rgb9e5=PACKED_OUT,LOCAL_MEAN_SUMS,ALBEDO_RGB9E5
                          first_history_sums_albedo_rgb9e5=PACKED_OUT,HISTORY,LOCAL_MEAN_SUMS,ALBEDO_RGB9E5
                          middle=PACKED_IN,PACKED_OUT middle_history=PACKED_IN,PACKED_OUT,HISTORY
                          middle_corrects_history=PACKED_IN,PACKED_OUT,CORRECTS_HISTORY
                          last=PACKED_IN last_history=PACKED_IN,HISTORY last_sums=PACKED_IN,LOCAL_MEAN_SUMS
                          last_sums_rgb9e5=PACKED_IN,LOCAL_MEAN_SUMS,RGB9E5_OUT
                          last_composite=PACKED_IN,COMPOSITE last_history_composite=PACKED_IN,HISTORY,COMPOSITE
                          last_composite_half=PACKED_IN,COMPOSITE,HDR_HALF
                          last_history_composite_half=PACKED_IN,HISTORY,COMPOSITE,HDR_HALF
                          last_composite_albedo_rgb9e5=PACKED_IN,COMPOSITE,ALBEDO_RGB9E5
                          last_history_composite_albedo_rgb9e5=PACKED_IN,HISTORY,COMPOSITE,ALBEDO_RGB9E5
                          last_composite_half_albedo_rgb9e5=PACKED_IN,COMPOSITE,HDR_HALF,ALBEDO_RGB9E5
                          last_history_composite_half_albedo_rgb9e5=PACKED_IN,HISTORY,COMPOSITE,HDR_HALF,ALBEDO_RGB9E5)
asvgf_add_shader(composite SOURCE denoise/composite.comp VARIANTS one split=SPLIT local_mean=LOCAL_MEAN
                 local_mean_rgb9e5=LOCAL_MEAN,ILLUMINATION_RGB9E5
                 one_half=HDR_HALF split_half=SPLIT,HDR_HALF local_mean_half=LOCAL_MEAN,HDR_HALF
                 local_mean_rgb9e5_half=LOCAL_MEAN,ILLUMINATION_RGB9E5,HDR_HALF
                 one_albedo_rgb9e5=ALBEDO_RGB9E5 split_albedo_rgb9e5=SPLIT,ALBEDO_RGB9E5
                 local_mean_albedo_rgb9e5=LOCAL_MEAN,ALBEDO_RGB9E5
                 local_mean_rgb9e5_albedo_rgb9e5=LOCAL_MEAN,ILLUMINATION_RGB9E5,ALBEDO_RGB9E5
                 one_half_albedo_rgb9e5=HDR_HALF,ALBEDO_RGB9E5 split_half_albedo_rgb9e5=SPLIT,HDR_HALF,ALBEDO_RGB9E5
                 local_mean_half_albedo_rgb9e5=LOCAL_MEAN,HDR_HALF,ALBEDO_RGB9E5
                 local_mean_rgb9e5_half_albedo_rgb9e5=LOCAL_MEAN,ILLUMINATION_RGB9E5,HDR_HALF,ALBEDO_RGB9E5)
asvgf_add_shader(local_mean SOURCE denoise/local_mean.comp
                 VARIANTS blocks=BLOCKS blocks_rgb9e5=BLOCKS,FILTERED_RGB9E5 blocks_filtered=BLOCKS,TEMPORAL_SUMS box=BOX
                          apply apply_rgb9e5=FILTERED_RGB9E5)
asvgf_add_shader(pack_surface SOURCE denoise/pack_surface.comp)
# gradient_reprojected, temporal: the `halves` ones read the motion as one word of two halves (R32UI,
# common/motion.glsl), the others as floats (the virtual motion always: specular_motion is RGBA32F).
asvgf_add_shader(gradient_reprojected SOURCE denoise/gradient_reprojected.comp VARIANTS floats halves=MOTION_HALVES)
asvgf_add_shader(validate_inputs SOURCE denoise/validate_inputs.comp)
asvgf_add_shader(convert_inputs SOURCE denoise/convert_inputs.comp)
