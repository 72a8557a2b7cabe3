// tools/relgeo/cli/options.cpp
#include "cli/options.h"

#include <map>

namespace relgeo::tool {

void add_format_option(CLI::App& cmd, Format& format) {
  const std::map<std::string, Format> names = {{"text", Format::text}, {"json", Format::json}};
  cmd.add_option("--format", format, "output format on stdout: text (default) or json")
      ->transform(CLI::CheckedTransformer(names).description(""))
      ->type_name("text|json")
      ->default_str("text");
}

void add_kernel_option(CLI::App& cmd, std::string& kernel, std::string_view default_kernel, std::string_view help) {
  std::string text = help.empty() ? std::string("the kernel (listed by 'relgeo help')") : std::string(help);
  auto* opt = cmd.add_option("--kernel", kernel, text)->type_name("KERNEL");
  if (!default_kernel.empty()) opt->default_str(std::string(default_kernel));
}

void add_file_operand(CLI::App& cmd, std::string& file, const std::string& flag, const std::string& help) {
  const auto set = [&file, flag](const std::string& value) {
    if (!file.empty())
      throw Usage_error("give the " + flag + " file once: either positionally or with --" + flag + " (got '" + file +
                        "' and '" + value + "')");
    file = value;
  };
  cmd.add_option_function<std::string>("--" + flag, set, help)->type_name("FILE");
  cmd.add_option_function<std::string>(flag, set, help + ", the same as --" + flag)->type_name("FILE");
}

void add_output_option(CLI::App& cmd, std::string& file, const std::string& flag, const std::string& help) {
  cmd.add_option("--" + flag, file, help)->type_name("FILE");
}

}  // namespace relgeo::tool
