# ASVGF_SANITIZE=ON builds everything with AddressSanitizer and UndefinedBehaviorSanitizer.
option(ASVGF_SANITIZE "Build with AddressSanitizer and UndefinedBehaviorSanitizer" OFF)
if(ASVGF_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
  add_link_options(-fsanitize=address,undefined)
  # Executables not position-independent: the sanitizers' per-check data made 1.7 M relative
  # relocations in asvgf, 0.3 s of every start (the fault sweeps start about a thousand processes).
  string(APPEND CMAKE_EXE_LINKER_FLAGS " -no-pie")
endif()

# Called once at the end of the top-level CMakeLists.txt: under ASVGF_SANITIZE every executable
# of the project gets keep_modules_loaded.cpp (why: that file's comment), so that LeakSanitizer
# names the library of each leak and tests/asan/lsan.supp can suppress Mesa's and the loader's.
function(asvgf_sanitize_executables)
  if(NOT ASVGF_SANITIZE)
    return()
  endif()
  set(pending ${CMAKE_SOURCE_DIR})
  while(pending)
    list(POP_FRONT pending dir)
    get_property(subdirs DIRECTORY ${dir} PROPERTY SUBDIRECTORIES)
    list(APPEND pending ${subdirs})
    get_property(targets DIRECTORY ${dir} PROPERTY BUILDSYSTEM_TARGETS)
    foreach(target ${targets})
      get_target_property(type ${target} TYPE)
      if(type STREQUAL "EXECUTABLE")
        target_sources(${target} PRIVATE ${CMAKE_SOURCE_DIR}/tools/cmake/keep_modules_loaded.cpp)
      endif()
    endforeach()
  endwhile()
endfunction()
