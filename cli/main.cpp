// Placeholder until the CLI lands (issue 4): prints the version.
#include <cstdio>
int main() { std::puts("jtracer-cli " JT_VERSION); }
