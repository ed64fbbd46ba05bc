#include <whiskermap/cli/WhiskerMapApp.h>

int main(int argc, char** argv) { return whiskermap::cli::WhiskerMapApp::main(argc, argv); }
