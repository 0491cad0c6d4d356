// One include, named by the target that compiles it (tests/layers/CMakeLists.txt): whether it
// compiles says whether the target's layer can see that header.
#include PROBE_HEADER
