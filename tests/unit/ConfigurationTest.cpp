#include "penumbra/rhi/Configuration.hpp"
#include "penumbra/rhi/Error.hpp"

#include <gtest/gtest.h>

namespace penumbra::rhi {
namespace {

TEST(ConfigurationTest, NamesRoundTrip)
{
    for (const NamedConfiguration& c : namedConfigurations())
        EXPECT_EQ(configurationName(parseConfiguration(c.name)), c.name);
}

TEST(ConfigurationTest, OnlyOpenGlHasANoClipControlMode)
{
    for (const NamedConfiguration& c : namedConfigurations())
        EXPECT_TRUE(c.desc.clipControl || c.desc.backend == Backend::OpenGL) << c.name;
}

TEST(ConfigurationTest, UnknownNameListsTheValidOnes)
{
    try {
        parseConfiguration("direct3d");
        FAIL() << "no error for an unknown configuration";
    } catch (const Error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("'direct3d'"), std::string::npos) << message;
        for (const NamedConfiguration& c : namedConfigurations())
            EXPECT_NE(message.find(c.name), std::string::npos) << message;
    }
}

} // namespace
} // namespace penumbra::rhi
