// A user technique's parameter values (techniques/user/user_technique.h): its rows are made from
// its file's header at run time, so their values live in one map rather than in struct members.
#pragma once
#include <map>
#include <string>

namespace ssao {

struct UserSettings {
    // "user.NAME.param" -> value as the row holds it (a float row's value rounded to float, an int,
    // enum or bool's a whole number); a key that is absent holds the header's default.
    std::map<std::string, double> values;
};

} // namespace ssao
