// Never built: tests/packaging/add_subdirectory_test.sh only configures.
#include "clients/remote/client.h"
int main() { return 0; }
