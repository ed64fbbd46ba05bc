#include <whiskermap/cli/WhiskerImportApp.h>

int main(int argc, char** argv) { return whiskermap::cli::WhiskerImportApp::main(argc, argv); }
