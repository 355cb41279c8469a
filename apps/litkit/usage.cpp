// SPDX-License-Identifier: MIT
#include "usage.hpp"

#include <iostream>
#include <string_view>
#include <vector>

#include "scene/words.hpp"

namespace litkit_cli {

namespace {

std::vector<const CLI::App*> commands(const CLI::App& app) {
    std::vector<const CLI::App*> all;
    for (const CLI::App* command : const_cast<CLI::App&>(app).get_subcommands({}))
        all.push_back(command);
    return all;
}

}  // namespace

std::string short_usage(const CLI::App& app) {
    std::string text = "usage: litkit COMMAND [options]\n\ncommands:\n";
    std::size_t widest = 0;
    for (const CLI::App* command : commands(app))
        widest = std::max(widest, command->get_name().size());
    for (const CLI::App* command : commands(app)) {
        text += "  " + command->get_name() +
                std::string(widest + 2 - command->get_name().size(), ' ') +
                command->get_description() + "\n";
    }
    return text +
           "\n'litkit render' alone draws the default scene; 'litkit COMMAND --help' lists a "
           "command's options.\nRun with --help for more information.\n";
}

std::optional<int> check_command(const CLI::App& app, int argc, char** argv) {
    if (argc < 2) {
        std::cerr << short_usage(app);
        return 2;
    }
    const std::string_view first = argv[1];
    if (first.starts_with("-")) return std::nullopt;  // --help, --version
    std::vector<std::string> names;
    for (const CLI::App* command : commands(app)) {
        if (command->get_name() == first) return std::nullopt;
        names.push_back(command->get_name());
    }
    const std::vector<std::string_view> candidates(names.begin(), names.end());
    std::cerr << "error: '" << first << "' is not a litkit command"
              << litkit::detail::did_you_mean(first, candidates) << "\n\n"
              << short_usage(app);
    return 2;
}

std::string option_suggestion(const CLI::App& app, int argc, char** argv) {
    const CLI::App* command = nullptr;
    for (const CLI::App* candidate : commands(app))
        if (candidate->parsed()) command = candidate;
    if (!command) return "";
    std::vector<std::string> names;
    for (const CLI::Option* option : const_cast<CLI::App*>(command)->get_options()) {
        for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
    }
    const std::vector<std::string_view> candidates(names.begin(), names.end());
    for (int i = 2; i < argc; ++i) {
        std::string_view word = argv[i];
        if (!word.starts_with("--")) continue;
        word = word.substr(0, word.find('='));
        bool known = false;
        for (std::string_view name : candidates) known = known || name == word;
        if (known) continue;
        const std::string suggestion = litkit::detail::did_you_mean(word, candidates);
        if (!suggestion.empty()) return "unknown option '" + std::string(word) + "'" + suggestion;
    }
    return "";
}

}  // namespace litkit_cli
