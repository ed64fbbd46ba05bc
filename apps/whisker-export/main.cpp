#include <whiskermap/cli/WhiskerExportApp.h>

int main(int argc, char** argv) { return whiskermap::cli::WhiskerExportApp::main(argc, argv); }
