// `vantage completion bash`: a bash completion script made from the command's own option table
// (the CLI11 tree of every subcommand), so that it lists exactly the options `--help` does.

#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "command.h"

namespace vantage::cli {
namespace {

// The options of `app` as typed: -x and --name forms, in the order of --help.
std::string option_words(const CLI::App& app) {
  std::string out;
  for (const CLI::Option* option : app.get_options()) {
    if (!option->nonpositional()) continue;
    for (const std::string& name : option->get_snames()) out += " -" + name;
    for (const std::string& name : option->get_lnames()) out += " --" + name;
  }
  return out.empty() ? out : out.substr(1);
}

std::vector<const CLI::App*> subcommands(const CLI::App& app) {
  return app.get_subcommands([](const CLI::App*) { return true; });
}

// One `case` arm per command path ("place", "layout snap"): its options, then its subcommands.
void write_cases(const CLI::App& app, const std::string& path, std::ostream& out) {
  std::string words = option_words(app);
  for (const CLI::App* sub : subcommands(app)) words += " " + sub->get_name();
  out << "    \"" << path << "\") words=\"" << words << "\" ;;\n";
  for (const CLI::App* sub : subcommands(app)) {
    write_cases(*sub, path.empty() ? sub->get_name() : path + " " + sub->get_name(), out);
  }
}

std::string bash_script(const CLI::App& root) {
  std::ostringstream out;
  out << "# bash completion for vantage, made by `vantage completion bash` from its option table.\n"
         "_vantage() {\n"
         "  local cur=${COMP_WORDS[COMP_CWORD]} path=\"\" word words i\n"
         "  # The command path: the words before the cursor that name subcommands.\n"
         "  for ((i = 1; i < COMP_CWORD; i++)); do\n"
         "    word=${COMP_WORDS[i]}\n"
         "    case \"${path:+$path }$word\" in\n";
  std::vector<std::string> paths;
  std::vector<const CLI::App*> stack = subcommands(root);
  std::vector<std::string> prefixes(stack.size());
  for (std::size_t k = 0; k < stack.size(); ++k) {
    const CLI::App* app = stack[k];
    const std::string path =
        prefixes[k].empty() ? app->get_name() : prefixes[k] + " " + app->get_name();
    paths.push_back(path);
    for (const CLI::App* sub : subcommands(*app)) {
      stack.push_back(sub);
      prefixes.push_back(path);
    }
  }
  for (const std::string& path : paths)
    out << "      \"" << path << "\") path=\"" << path << "\" ;;\n";
  out << "    esac\n"
         "  done\n"
         "  case \"$path\" in\n";
  write_cases(root, "", out);
  out << "  esac\n"
         "  # Options after a dash, else subcommands; file names otherwise (complete -o default).\n"
         "  if [[ $cur == -* ]]; then\n"
         "    COMPREPLY=($(compgen -W \"$words\" -- \"$cur\"))\n"
         "  else\n"
         "    COMPREPLY=($(compgen -W \"$(printf '%s\\n' $words | grep -v '^-')\" -- \"$cur\"))\n"
         "  fi\n"
         "}\n"
         "complete -o default -F _vantage vantage\n";
  return out.str();
}

}  // namespace

Command add_completion_command(CLI::App& root) {
  auto shell = std::make_shared<std::string>();
  CLI::App* sub = root.add_subcommand(
      "completion",
      "Print the shell completion script of vantage, made from its option table "
      "(bash: source it, or install it as bash-completion/completions/vantage)");
  sub->add_option("SHELL", *shell, "the shell")->required()->check(CLI::IsMember({"bash"}));
  const CLI::App* root_app = &root;
  return {sub, [root_app] {
            std::cout << bash_script(*root_app);
            return kExitOk;
          }};
}

}  // namespace vantage::cli
