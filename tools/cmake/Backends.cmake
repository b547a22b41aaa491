# asvgf_register_backend(TARGET SOURCE): a HAL backend's registration, called from its own folder.
# SOURCE (relative to that folder) defines hal::registry::<TARGET>_backends(); hal/registry builds it
# into hal_registry, so the backend's own library needs nothing of the registry.
function(asvgf_register_backend target source)
  set_property(GLOBAL APPEND PROPERTY ASVGF_BACKEND_TARGETS ${target})
  set_property(GLOBAL APPEND PROPERTY ASVGF_BACKEND_SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/${source})
endfunction()
