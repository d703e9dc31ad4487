// Owner of a precompiled header that the test programs reuse (tests/CMakeLists.txt): it is
// compiled only for the PCH, with the flags of a test program.
