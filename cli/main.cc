// vantage — how good is a fiducial layout for pose from a single affine image, and how to make it
// better. See README.md for the subcommands and their JSON contracts.

#include <iostream>
#include <string>
#include <vector>

#include "command.h"
#include "vantage/analysis/common.h"
#include "vantage/io/printable.h"
#include "vantage/io/text_file.h"

namespace {

/// Errors are exactly one line on stderr: line breaks become spaces, other control characters
/// (an escape sequence in a file name, say) \xNN.
void print_error(const std::string& kind, std::string message) {
  for (char& c : message)
    if (c == '\n' || c == '\r') c = ' ';
  std::cerr << "vantage: " << kind << ": " << vantage::io::printable(message) << std::endl;
}

/// The first word when it is neither an option nor a subcommand ("vantage frob"), else empty.
std::string unknown_subcommand(CLI::App& app, int argc, char** argv) {
  if (argc < 2 || argv[1][0] == '-') return "";
  const std::string word = argv[1];
  for (const CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) {
    if (sub->check_name(word)) return "";
  }
  return word;
}

/// "analyze, orient, ..." in registration order.
std::string subcommand_names(CLI::App& app) {
  std::string names;
  for (const CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) {
    names += (names.empty() ? "" : ", ") + sub->get_name();
  }
  return names;
}

/// The option `name` of the deepest parsed subcommand that has it, or nullptr.
const CLI::Option* parsed_option(const CLI::App& app, const std::string& name) {
  for (const CLI::App* sub : app.get_subcommands()) {
    if (const CLI::Option* deeper = parsed_option(*sub, name)) return deeper;
  }
  return app.get_option_no_throw(name);
}

/// CLI11's "Could not convert: --name = value" as what the option takes: a whole number (with
/// an example of writing 1e5 as digits) or a number. Other messages stay as CLI11 words them.
std::string conversion_message(const CLI::App& app, const CLI::ConversionError& error) {
  const std::string text = error.what();
  const std::string head = "Could not convert: ";
  const std::size_t equals = text.find(" = ");
  if (text.rfind(head, 0) != 0 || equals == std::string::npos) return text;
  const std::string name = text.substr(head.size(), equals - head.size());
  const std::string value = text.substr(equals + 3);
  const CLI::Option* option = parsed_option(app, name);
  const std::string type = option == nullptr ? "" : option->get_type_name();
  if (type == "INT" || type == "UINT") {
    return name + ": \"" + value + "\" is not a whole number (write its digits: 100000, not 1e5)";
  }
  if (type == "FLOAT") return name + ": \"" + value + "\" is not a number";
  return text;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace vantage::cli;
  // An interrupted write (Ctrl-C, kill) leaves neither its hidden temporary nor its lock file.
  vantage::io::remove_partial_files_on_signal();
  CLI::App app{
      "vantage: evaluate and design fiducial layouts for pose estimation from a single affine "
      "image (McInroy, Erwin & Robertson), with the estimators of Haralick et al. and Wu & Wu.",
      "vantage"};
  app.require_subcommand(1, 1);
  app.set_version_flag("--version", std::string(VANTAGE_VERSION));

  const std::vector<Command> commands = {
      add_analyze_command(app), add_orient_command(app),     add_design_command(app),
      add_place_command(app),   add_weights_command(app),    add_pose_command(app),
      add_layout_command(app),  add_simulate_command(app),   add_experiment_command(app),
      add_plot_command(app),    add_crb_command(app),        add_tre_command(app),
      add_ident_command(app),   add_completion_command(app),
  };

  const std::string unknown = unknown_subcommand(app, argc, argv);
  if (!unknown.empty()) {
    print_error("error", "unknown subcommand \"" + unknown + "\"; the subcommands are " +
                             subcommand_names(app) + " (see vantage --help)");
    return kExitBadInput;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ConversionError& e) {
    print_error("error", conversion_message(app, e));
    return kExitBadInput;
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return app.exit(e);
    print_error("error", e.what());
    return kExitBadInput;
  }

  try {
    for (const Command& command : commands) {
      if (command.app->parsed()) return command.run();
    }
  } catch (const vantage::InvalidArgument& e) {
    print_error("error", e.what());
    return kExitBadInput;
  } catch (const vantage::io::WriteError& e) {
    print_error("error", e.what());
    return kExitFailure;
  } catch (const std::exception& e) {
    print_error("internal error", e.what());
    return kExitFailure;
  }
  print_error("error", "no subcommand given (see vantage --help)");
  return kExitBadInput;
}
