// The manual's generated pages, from the definitions they document: docs/commands.md from the
// command line's own options (`ssaolab docs commands`), docs/parameters.md from the parameter table
// (`ssaolab docs parameters`). tests/cli/test_cli_docs.cpp fails when a committed page is stale.
#pragma once
#include <string>

namespace CLI {
class App;
}

namespace ssao {

std::string commandReference(const CLI::App& app);
std::string parameterReference();

} // namespace ssao
