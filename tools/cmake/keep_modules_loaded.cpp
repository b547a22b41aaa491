// Linked into every executable of the ASVGF_SANITIZE build only (tools/cmake/Sanitizers.cmake).
// The Vulkan loader and libglvnd dlclose() the driver (Mesa lavapipe/llvmpipe) and the validation
// layer when the instance or display goes away; LeakSanitizer reports at exit, when those modules
// are gone, so their leaks show as "<unknown module>" and no suppression can name them. An
// executable's own dlclose() takes precedence over libc's for every library in the process; this
// one keeps the module loaded (the process is about to exit anyway) so that each leak names its
// library and tests/asan/lsan.supp can suppress third-party ones by library.
extern "C" int dlclose(void*) {
  return 0;
}
