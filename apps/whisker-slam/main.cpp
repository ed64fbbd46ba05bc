#include <whiskermap/cli/WhiskerSlamApp.h>

int main(int argc, char** argv) { return whiskermap::cli::WhiskerSlamApp::main(argc, argv); }
