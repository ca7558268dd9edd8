#include "GpuTesting.hpp"

#include <cstring>
#include <gtest/gtest.h>

// Usage: penumbra_gpu_tests --configuration <name> [gtest flags]
int main(int argc, char** argv)
{
    ::testing::InitGoogleTest(&argc, argv);
    for (int i = 1; i + 1 < argc; ++i)
        if (std::strcmp(argv[i], "--configuration") == 0)
            penumbra::testing::setConfiguration(argv[i + 1]);
    return RUN_ALL_TESTS();
}
