// SPDX-License-Identifier: MIT
// litkit: the command-line tool. Thin by design: it parses arguments, calls
// the library and decides how results and errors are shown and which exit
// status they get (docs/spec.md §6: 0 success, 1 a file could not be read or written,
// 2 invalid input or usage). Each command is a file of its own (commands.hpp);
// this one adds them, runs the one named and maps errors to exit statuses.
#include <signal.h>
#include <CLI/CLI.hpp>

#include <iostream>
#include <new>
#include <string>
#include <string_view>

#include "commands.hpp"
#include "completion.hpp"
#include "core/files.hpp"
#include "heap.hpp"
#include "litkit/error.hpp"
#include "litkit/gl_renderer.hpp"
#include "modules.hpp"
#include "options.hpp"
#include "usage.hpp"
#include "version.hpp"

namespace {

using namespace litkit_cli;

// A catchable signal ends the run as it would have, but first removes the
// temporary files of a write in progress (docs/reliability.md). A file size
// limit (ulimit -f) makes write() fail with EFBIG instead of killing the
// process, so that the failed write is reported and cleaned up like a full disk.
extern "C" void remove_temporaries_and_end(int signal_number) {
    litkit::remove_registered_temporaries();
    ::raise(signal_number);  // SA_RESETHAND | SA_NODEFER: the default action, now
}

void install_signal_handlers() {
    struct sigaction action {};
    action.sa_handler = remove_temporaries_and_end;
    action.sa_flags = SA_RESETHAND | SA_NODEFER;
    sigemptyset(&action.sa_mask);
    for (int signal_number : {SIGINT, SIGTERM, SIGHUP, SIGQUIT}) {
        struct sigaction previous {};
        // A signal ignored by whoever started us (nohup) stays ignored.
        if (::sigaction(signal_number, nullptr, &previous) == 0 && previous.sa_handler == SIG_IGN)
            continue;
        ::sigaction(signal_number, &action, nullptr);
    }
    ::signal(SIGXFSZ, SIG_IGN);
}

}  // namespace

int main(int argc, char** argv) {
    litkit_cli::use_large_pages_for_the_heap();
    CLI::App app{"litkit: renders a lit, shaded 3D scene from a scene file"};
    // The text is made only when asked for (version.cpp).
    app.set_version_flag("--version", litkit_cli::version_text,
                         "Show the version and the build's features, and exit");
    bool quiet = false;
    app.add_flag("-q,--quiet", quiet,
                 "Say nothing but errors (no 'litkit: wrote', warnings or progress)");
    // The bash completion script, made from the commands and options below
    // (completion.cpp): the build writes it, `cmake --install` installs it.
    // Not in --help (an empty group).
    app.add_flag_callback(
           "--bash-completion",
           [&app] {
               std::cout << litkit_cli::bash_completion(app);
               throw CLI::Success();
           },
           "Print the bash completion script")
        ->group("");
    app.require_subcommand(1);
    // Lets `--version` (and any option of the top level) follow a command:
    // `litkit render --version` works as docs/spec.md §8 asks.
    app.fallthrough();

    // Only the command at hand gets its options: CLI11 spends about 3 µs
    // on each option it adds (0.3 ms for all of them, a twentieth of
    // `litkit render`'s whole run). Every command is still listed, and
    // --help, --version or no command at all define everything.
    const std::string_view command_word = argc > 1 ? std::string_view(argv[1]) : std::string_view();
    const bool define_all = command_word.empty() || command_word.starts_with("-");
    const DefinesOptions defines = [&](const CLI::App& command) {
        return define_all || command.get_name() == command_word;
    };

    // In the order `litkit --help` lists them.
    const Command commands[] = {
        add_render(app, defines),  add_check(app, defines),     add_init(app, defines),
        add_export(app, defines),  add_compare(app, defines),   add_view(app, defines),
        add_explain(app, defines), add_turntable(app, defines), add_bench(app, defines),
    };

    if (const auto status = litkit_cli::check_command(app, argc, argv)) return *status;
    try {
        app.parse(argc, argv);
    } catch (const CLI::Success& success) {
        return app.exit(success);
    } catch (const CLI::ParseError& error) {
        app.exit(error);
        const std::string suggestion = litkit_cli::option_suggestion(app, argc, argv);
        if (!suggestion.empty()) std::cerr << "hint: " << suggestion << "\n";
        return exit_invalid;
    }

    litkit_cli::set_quiet(quiet);

    const Command* command = nullptr;
    for (const Command& candidate : commands)
        if (candidate.app->parsed()) command = &candidate;
    if (!command) return exit_invalid;

    if (!command->leaves_signals_to_sdl) install_signal_handlers();
    try {
        return command->run();
    } catch (const litkit::SceneError& error) {
        print_diagnostics(error.diagnostics());
        if (!quiet) print_diagnostics(error.warnings());
        return exit_invalid;
    } catch (const litkit::IoError& error) {
        std::cerr << error.what() << "\n";
        return exit_io;
    } catch (const litkit::GlError& error) {
        std::cerr << "error: " << error.what() << "\n"
                  << "hint: render without OpenGL with --backend cpu\n";
        return exit_io;
    } catch (const UsageError& error) {
        std::cerr << "error: " << error.message << "\n";
        return exit_invalid;
    } catch (const litkit_cli::ModuleError& error) {
        std::cerr << "error: " << error.message << "\n";
        return exit_io;
    } catch (const std::bad_alloc&) {
        // Never "std::bad_alloc": what ran out, and what to do about it.
        std::cerr << "error: out of memory while "
                  << (command->renders ? "building the meshes or rendering"
                                       : "reading or checking the scene")
                  << "; lower the objects' tessellation, the image size or --max-triangles "
                     "(docs/reliability.md)\n";
        return exit_io;
    } catch (const std::exception& error) {
        std::cerr << "error: " << error.what() << "\n";
        return exit_io;
    }
}
