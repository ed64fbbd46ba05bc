#include <whiskermap/cli/WhiskerSimApp.h>

int main(int argc, char** argv) { return whiskermap::cli::WhiskerSimApp::main(argc, argv); }
