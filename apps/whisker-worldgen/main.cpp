#include <whiskermap/cli/WhiskerWorldgenApp.h>

int main(int argc, char** argv) { return whiskermap::cli::WhiskerWorldgenApp::main(argc, argv); }
