// Linked into the fuzz targets only: MRPT's exceptions record a symbolised call stack
// (backtrace + backtrace_symbols), which costs about a millisecond per throw and made
// targets that reach MRPT's reader 10x slower. This definition, found before libc's, gives
// empty stacks; nothing else about the code under test changes.
extern "C" int backtrace(void** /*buffer*/, int /*size*/) { return 0; }
