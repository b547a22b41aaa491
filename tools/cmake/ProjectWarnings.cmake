# Project-wide warnings; errors when CI is set in the environment or ASVGF_WERROR is on.
option(ASVGF_WERROR "Treat warnings as errors" OFF)
if(DEFINED ENV{CI} AND NOT "$ENV{CI}" STREQUAL "" AND NOT "$ENV{CI}" STREQUAL "false")
  set(ASVGF_WERROR ON CACHE BOOL "Treat warnings as errors" FORCE)
endif()

# Applied per target (project code only), never to third-party headers, which are SYSTEM includes.
function(asvgf_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor
                                           -Wold-style-cast -Wcast-align -Woverloaded-virtual
                                           -Wimplicit-fallthrough
                                           # Vulkan structs are initialised as {sType} on purpose.
                                           -Wno-missing-field-initializers)
  if(ASVGF_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
