// A shared library named like a transport plugin but without its entry point.
extern "C" __attribute__((visibility("default"))) int not_a_transport() { return 0; }
