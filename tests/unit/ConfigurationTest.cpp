#include "penumbra/backends/CreateDevice.hpp"
#include "penumbra/rhi/Error.hpp"

#include <gtest/gtest.h>

namespace penumbra {
namespace {

using rhi::BackendRegistration;
using rhi::DeviceDesc;
using rhi::Error;
using rhi::NamedConfiguration;
using rhi::UnsupportedError;

TEST(ConfigurationTest, NamesRoundTrip)
{
    for (const NamedConfiguration& c : namedConfigurations())
        EXPECT_EQ(configurationName(parseConfiguration(c.name)), c.name);
}

TEST(ConfigurationTest, EachBackendRegistersItsOwnConfigurations)
{
    for (const BackendRegistration& b : registeredBackends()) {
        EXPECT_FALSE(b.configurations.empty()) << b.name;
        for (const NamedConfiguration& c : b.configurations)
            EXPECT_EQ(c.desc.backend, b.name) << c.name;
    }
}

// CMake's list (penumbra_backend(... CONFIGURATIONS ...), which names the per-configuration tests) and
// the C++ registrations must name the same configurations in the same order.
TEST(ConfigurationTest, CMakeAndTheRegistrationsAgree)
{
    std::string registered;
    for (const NamedConfiguration& c : namedConfigurations())
        registered += (registered.empty() ? "" : ",") + c.name;
    EXPECT_EQ(registered, PENUMBRA_TEST_CONFIGURATIONS);
}

TEST(ConfigurationTest, UnknownBackendIsUnsupported)
{
    DeviceDesc desc;
    desc.backend = "metal";
    EXPECT_THROW(createDevice(desc), UnsupportedError);
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
} // namespace penumbra
