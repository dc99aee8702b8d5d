// Catch2 main of test_fem, in its own translation unit so that editing the tests does not rebuild it.
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>
