// The Catch2 main of every test executable; doubles are printed with all 17 digits.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

int main(int argc, char *argv[])
{
  Catch::StringMaker<double>::precision = 17;
  return Catch::Session().run(argc, argv);
}
