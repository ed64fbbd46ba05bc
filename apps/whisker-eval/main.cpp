#include <whiskermap/cli/WhiskerEvalApp.h>

int main(int argc, char** argv) { return whiskermap::cli::WhiskerEvalApp::main(argc, argv); }
