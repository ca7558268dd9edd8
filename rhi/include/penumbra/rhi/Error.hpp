#pragma once

#include <stdexcept>
#include <string>

namespace penumbra::rhi {

// Every failure the RHI reports: bad input, a missing driver, a refused capability.
// The message names what failed and why; nothing is retried or faked silently.
class Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A GLSL source that glslang rejected; what() carries glslang's log ("file:line: message").
class ShaderCompileError : public Error {
public:
    using Error::Error;
};

// The device was lost (a GPU hang or reset, a driver failure) while it worked: what() names the API's code. Every
// object of the device is then unusable but for its destruction; make a new device to go on.
class DeviceLostError : public Error {
public:
    using Error::Error;
};

// The driver does not offer what was asked (a missing extension, a format feature).
class UnsupportedError : public Error {
public:
    using Error::Error;
};

} // namespace penumbra::rhi
