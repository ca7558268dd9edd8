// Compiled into every program that loads the Mesa drivers (see apps/CMakeLists.txt).
#if defined(__SANITIZE_ADDRESS__)
// LeakSanitizer is off in these programs: Mesa keeps allocations until exit in code built without
// frame pointers, so LSan sees one-frame stacks it cannot attribute to a module to suppress.
// AddressSanitizer and UndefinedBehaviorSanitizer stay on; the CPU-only tests keep leak checking.
extern "C" const char* __asan_default_options();
extern "C" const char* __asan_default_options() { return "detect_leaks=0"; }
#endif
