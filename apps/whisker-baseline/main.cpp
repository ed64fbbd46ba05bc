#include <whiskermap/cli/WhiskerBaselineApp.h>

int main(int argc, char** argv) { return whiskermap::cli::WhiskerBaselineApp::main(argc, argv); }
