// A pass's configuration: everything its output depends on besides the contents of the resources
// it reads - the constant blocks it uploads, the frame constants its shaders read and the CPU
// choices it makes (which textures it binds, which variant it compiles) - as one plain struct that
// one pure function derives from the settings and the frame (ConfiguredPass::config). The frame
// graph keys the pass on that struct's bytes, and the pass's run() receives the struct and nothing
// else of the settings: a value the pass uses can only come from the config, so a change to it
// always re-runs the pass, and a change to anything else never does (issue 15 §2).
//
// The struct is compared byte for byte, so it must have no padding (whose bytes are unspecified):
// declare it between SSAO_CONFIG_BEGIN and SSAO_CONFIG_END, which make any padding a compile error
// (-Wpadded), and build it from 4-byte fields (float, int32_t, enums with an int32_t base, glm
// vectors and matrices, the std140 blocks of shaders/include).
#pragma once
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <typeinfo>

#define SSAO_CONFIG_BEGIN _Pragma("GCC diagnostic push") _Pragma("GCC diagnostic error \"-Wpadded\"")
#define SSAO_CONFIG_END _Pragma("GCC diagnostic pop")

namespace ssao {

class ConfigKey {
  public:
    ConfigKey() = default;
    template <class C> static ConfigKey of(const C& c) {
        static_assert(std::is_trivially_copyable_v<C> && std::is_standard_layout_v<C>,
                      "a pass config is a plain struct (graph/pass_config.h)");
        ConfigKey k;
        k.type_ = &typeid(C);
        k.bytes_.assign(reinterpret_cast<const char*>(&c), sizeof c);
        return k;
    }
    bool empty() const { return type_ == nullptr; }
    bool operator==(const ConfigKey& o) const {
        return (type_ == o.type_ || (type_ && o.type_ && *type_ == *o.type_)) && bytes_ == o.bytes_;
    }
    bool operator!=(const ConfigKey& o) const { return !(*this == o); }
    template <class C> C as() const {
        if (!type_ || *type_ != typeid(C) || bytes_.size() != sizeof(C))
            throw std::logic_error("pass config holds another type than the pass reads");
        C c;
        std::memcpy(static_cast<void*>(&c), bytes_.data(), sizeof c);
        return c;
    }

  private:
    const std::type_info* type_ = nullptr;
    std::string bytes_;
};

SSAO_CONFIG_BEGIN
// The config of a pass whose output depends on nothing but its external data (Pass::externalVersion).
struct NoConfig {
    int32_t none = 0;
};
SSAO_CONFIG_END

} // namespace ssao
