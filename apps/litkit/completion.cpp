// SPDX-License-Identifier: MIT
#include "completion.hpp"

#include <string>
#include <vector>

namespace litkit_cli {

namespace {

// The words of a name list a validator shows ("TEXT:{flat,gouraud}" -> "flat gouraud").
std::string choices_of(const CLI::Option& option) {
    const std::string type = option.get_type_name();
    const std::size_t open = type.find(":{");
    const std::size_t close = type.find('}', open);
    if (open == std::string::npos || close == std::string::npos) return "";
    std::string words = type.substr(open + 2, close - open - 2);
    for (char& c : words)
        if (c == ',') c = ' ';
    return words;
}

// Every visible name of the options of `command` ("-o --output --width ..."),
// with or without --help.
std::string option_names(const CLI::App& command, bool help = true) {
    std::string names;
    for (const CLI::Option* option : command.get_options()) {
        if (option->get_group().empty() || !option->nonpositional()) continue;
        if (!help && option == command.get_help_ptr()) continue;
        for (const std::string& name : option->get_snames()) names += " -" + name;
        for (const std::string& name : option->get_lnames()) names += " --" + name;
    }
    return names;
}

// `case $prev in` arms for the options of `command` that take a value.
std::string value_arms(const CLI::App& command) {
    std::string arms;
    for (const CLI::Option* option : command.get_options()) {
        if (option->get_group().empty() || !option->nonpositional()) continue;
        if (option->get_expected_max() == 0) continue;  // a flag
        std::string pattern;
        for (const std::string& name : option->get_snames()) pattern += "|-" + name;
        for (const std::string& name : option->get_lnames()) pattern += "|--" + name;
        const std::string choices = choices_of(*option);
        const bool text = option->get_type_name().starts_with("TEXT");
        arms += "                " + pattern.substr(1) + ") ";
        if (!choices.empty()) {
            arms += "COMPREPLY=($(compgen -W \"" + choices + "\" -- \"$cur\")); return ;;\n";
        } else if (text) {
            arms += "COMPREPLY=($(compgen -f -- \"$cur\")); return ;;\n";
        } else {
            arms += "return ;;  # a number\n";
        }
    }
    return arms;
}

}  // namespace

std::string bash_completion(const CLI::App& app) {
    auto& all = const_cast<CLI::App&>(app);
    const std::string top_options = option_names(app, false);  // after a command too
    std::string commands;
    std::string arms;
    for (const CLI::App* command : all.get_subcommands({})) {
        commands += (commands.empty() ? "" : " ") + command->get_name();
        arms += "        " + command->get_name() + ")\n            options=\"" +
                option_names(*command).substr(1) + top_options + "\"\n";
        const std::string values = value_arms(*command);
        if (!values.empty()) arms += "            case $prev in\n" + values + "            esac\n";
        arms += "            ;;\n";
    }
    return "# bash completion for litkit " LITKIT_VERSION
           ", written by `litkit --bash-completion`\n"
           "# from the program's own commands and options.\n"
           "_litkit() {\n"
           "    local cur=${COMP_WORDS[COMP_CWORD]} prev=${COMP_WORDS[COMP_CWORD-1]}\n"
           "    local command= options= i\n"
           "    for ((i = 1; i < COMP_CWORD; i++)); do\n"
           "        case ${COMP_WORDS[i]} in\n"
           "            -*) ;;\n"
           "            *) command=${COMP_WORDS[i]}; break ;;\n"
           "        esac\n"
           "    done\n"
           "    COMPREPLY=()\n"
           "    case $command in\n"
           "        \"\")\n"
           "            options=\"" +
           option_names(app).substr(1) +
           "\"\n"
           "            ;;\n" +
           arms +
           "        *) return ;;\n"
           "    esac\n"
           "    if [[ $cur == -* ]]; then\n"
           "        COMPREPLY=($(compgen -W \"$options\" -- \"$cur\"))\n"
           "    elif [[ -z $command ]]; then\n"
           "        COMPREPLY=($(compgen -W \"" +
           commands +
           "\" -- \"$cur\"))\n"
           "    else\n"
           "        COMPREPLY=($(compgen -f -- \"$cur\"))\n"
           "    fi\n"
           "}\n"
           "complete -o filenames -o bashdefault -F _litkit litkit\n";
}

}  // namespace litkit_cli
