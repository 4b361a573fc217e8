#include <cstdio>

int main() {
  std::fputs("strata: the command line is being assembled\n", stderr);
  return 3;
}
