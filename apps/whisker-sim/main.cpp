#include <whiskermap/world/WhiskerSimApp.h>

int main(int argc, char** argv) { return whiskermap::world::WhiskerSimApp::main(argc, argv); }
