// The plugin's only exported symbol (everything else is hidden): the loader checks its ABI
// string, then calls create().
#include "fast_transport.hpp"
#include "plumb/transport/loader.hpp"

PLUMB_TRANSPORT_PLUGIN(plumb::transport::fastdds::FastTransport)
