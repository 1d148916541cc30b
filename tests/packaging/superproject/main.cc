// Never built: tests/packaging/add_subdirectory_test.sh only configures.
#include "client/client.h"
int main() { return 0; }
