// The program that compiles the test executables' precompiled header (tests/CMakeLists.txt,
// frictionlab_test_headers); the header is its only content.
int main() { return 0; }
