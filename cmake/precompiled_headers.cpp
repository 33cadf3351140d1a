// Compiles the shared precompiled headers (cmake/precompiled_headers.cmake).
