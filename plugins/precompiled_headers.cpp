// The library that compiles the plugins' precompiled header (plugins/CMakeLists.txt,
// frictionlab_plugin_headers); the header is its only content.
