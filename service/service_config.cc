#include "service/service_config.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <google/protobuf/io/tokenizer.h>
#include <google/protobuf/text_format.h>
#include <spdlog/common.h>

#include "codec/nearest_name.h"
#include "core/model_error.h"
#include "protocol/domain_id.h"
#include "service/service_config.pb.h"

namespace gc::service {
namespace {

class FileErrors : public google::protobuf::io::ErrorCollector {
 public:
  explicit FileErrors(std::string path) : path_(std::move(path)) {}
  void AddError(int line, int column, const std::string& message) override {
    if (first_.empty()) {
      const std::string guess = suggestion(message);
      std::string said = message;
      if (!guess.empty() && !said.empty() && said.back() == '.') said.pop_back();
      first_ = path_ + ":" + std::to_string(line + 1) + ":" + std::to_string(column + 1) + ": " +
               said + guess;
    }
  }

  /// "; did you mean 'threads'?" for a misspelt setting (protobuf: no field named "x").
  static std::string suggestion(const std::string& message) {
    static constexpr std::string_view kMarker = "no field named \"";
    const std::size_t at = message.find(kMarker);
    if (at == std::string::npos) return "";
    const std::size_t begin = at + kMarker.size();
    const std::string typed = message.substr(begin, message.find('"', begin) - begin);
    std::vector<std::string> names;
    const auto* type = gearcoupling::v1::ServiceConfig::descriptor();
    for (int i = 0; i < type->field_count(); ++i) names.push_back(type->field(i)->name());
    return codec::did_you_mean(typed, names);
  }
  const std::string& first() const { return first_; }

 private:
  std::string path_;
  std::string first_;
};

/// Why a file that does not parse might not: it is written as TOML, as the monitor's and the
/// dashboard's are (a `name = value` line), "" otherwise.
std::string toml_hint(const std::string& text) {
  static const std::regex toml_line(R"(^\s*[A-Za-z_][A-Za-z0-9_-]*\s*=)");
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    if (std::regex_search(line, toml_line)) {
      return " (this file is protobuf text format, `name: value`, with the fields of "
             "service/service_config.proto; monitor.conf and dashboard.conf are TOML, `name = "
             "value`: docs/deploy.md, \"Configuration files\")";
    }
  }
  return "";
}

}  // namespace

void apply_config_file(const std::string& path, ServiceConfig& config) {
  errno = 0;
  std::ifstream in(path);
  if (!in) {
    throw InvalidInput("--config", "cannot read \"" + path + "\": " + std::strerror(errno));
  }
  std::stringstream text;
  text << in.rdbuf();
  gearcoupling::v1::ServiceConfig file;
  google::protobuf::TextFormat::Parser parser;
  FileErrors errors(path);
  parser.RecordErrorsTo(&errors);
  if (!parser.ParseFromString(text.str(), &file)) {
    throw InvalidInput("--config", errors.first() + toml_hint(text.str()));
  }
  if (file.has_domain()) config.domain = file.domain();
  if (file.has_threads()) config.threads = file.threads();
  if (file.has_catalogue_dir()) config.catalogue_dir = file.catalogue_dir();
  if (file.has_log_level()) config.log_level = file.log_level();
  if (file.has_status_interval_s()) config.status_interval_s = file.status_interval_s();
  if (file.has_stats_log_interval_s()) config.stats_log_interval_s = file.stats_log_interval_s();
  if (file.has_liveliness_lease_s()) config.liveliness_lease_s = file.liveliness_lease_s();
  if (file.has_reply_match_timeout_s()) config.reply_match_timeout_s = file.reply_match_timeout_s();
  if (file.has_shutdown_grace_s()) config.shutdown_grace_s = file.shutdown_grace_s();
  if (file.has_reply_block_s()) config.reply_block_s = file.reply_block_s();
  if (file.has_departed_hold_s()) config.departed_hold_s = file.departed_hold_s();
  if (file.has_calculation_deadline_s()) {
    config.calculation_deadline_s = file.calculation_deadline_s();
  }
}

namespace {

// The command line of gearcoupling-service, bound to `command`: CLI11 assigns a flag's value
// only when it is given, and runs --config's callback first (options are processed in the
// order declared), so flags override the file wherever --config appears.
void declare_flags(CLI::App& app, ServiceCommand& command) {
  ServiceConfig& c = command.config;
  // A flag given twice: the last wins, as flags win over the file (a wrapper script adds to a
  // command line rather than editing it).
  app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  app.set_version_flag("--version", "gearcoupling-service " GC_VERSION);
  app.add_flag("--bash-completion", command.bash_completion, "print the bash completion script");
  app.get_formatter()->column_width(34);
  app.add_option_function<std::string>(
      "--config", [&c](const std::string& path) { apply_config_file(path, c); },
      "settings in protobuf text format (service/service_config.proto); flags override it")
      ->type_name("FILE");
  app.add_option("--domain", c.domain,
                 fmt::format("DDS domain id, 0..{}; the network comes from the Cyclone XML named by "
                             "CYCLONEDDS_URI (deploy/cyclonedds-loopback.xml)",
                             protocol::kMaxDomainId))
      ->type_name("N")->capture_default_str();
  app.add_option("-j,--jobs,--threads", c.threads,
                 "worker threads, 0 = one per core, 0..1024 (--threads: the older spelling)")
      ->type_name("N")->capture_default_str();
  app.add_option("--catalogue", c.catalogue_dir,
                 "directory of *.textproto couplings (default: the bundled NREL ones or "
                 "$GEARCOUPLING_CATALOG)")
      ->type_name("DIR");
  app.add_option("--log-level", c.log_level,
                 "trace, debug (one line per request), info, warn, error, off")
      ->type_name("LEVEL")->capture_default_str();
  const auto seconds = [&app](const std::string& names, double& value, const std::string& help) {
    app.add_option(names, value, help + " [s]")->type_name("S")->capture_default_str();
  };
  seconds("--status-interval-s,--status-interval", c.status_interval_s, "status topic period");
  seconds("--stats-interval-s,--stats-interval", c.stats_log_interval_s,
          "periodic stats log line");
  seconds("--lease-s,--lease", c.liveliness_lease_s, "liveliness lease of the status writer");
  seconds("--reply-match-timeout-s,--reply-match-timeout", c.reply_match_timeout_s,
          "longest a request waits (parked, before any work) for its client's reply reader, "
          "then it is dropped");
  seconds("--reply-block-s,--reply-block", c.reply_block_s,
          "longest a reply waits, retried without blocking a worker, for a client that does "
          "not acknowledge (slow, stopped, killed)");
  seconds("--departed-hold-s,--departed-hold", c.departed_hold_s,
          "then drop that client's requests for this long");
  seconds("--shutdown-grace-s,--shutdown-grace", c.shutdown_grace_s,
          "after SIGINT/SIGTERM keep answering this long, then exit");
  seconds("--deadline-s,--deadline", c.calculation_deadline_s,
          "a request not answered this long after it arrived (queued or computing) gets "
          "STATUS_DEADLINE_EXCEEDED, 1e-6..60");
  app.footer("Flags ending in -s take seconds; each older name without the unit is an alias.");
}

}  // namespace

ServiceCommand parse_service_command(const std::vector<std::string>& args) {
  ServiceCommand command;
  CLI::App app{"gearcoupling-service: crowned-tooth gear coupling calculations over DDS "
               "request/reply",
               "gearcoupling-service"};
  app.allow_extras();
  declare_flags(app, command);
  try {
    app.parse(std::vector<std::string>(args.rbegin(), args.rend()));  // CLI11 pops the back
  } catch (const CLI::CallForHelp&) {
    command.help = true;
    return command;
  } catch (const CLI::CallForVersion&) {
    command.version = true;
    return command;
  } catch (const CLI::ParseError& error) {
    throw InvalidInput("command line", error.what());
  }
  if (!app.remaining().empty()) {
    throw InvalidInput(app.remaining().front(), "unknown flag or stray argument (see --help)");
  }
  validate(command.config);
  return command;
}

void validate(const ServiceConfig& c) {
  if (c.domain < 0 || c.domain > protocol::kMaxDomainId) {
    throw InvalidInput("domain", c.domain, fmt::format("[0, {}]", protocol::kMaxDomainId));
  }
  if (c.threads > 1024) throw InvalidInput("threads", c.threads, "[0, 1024]; 0 = one per core");
  if (spdlog::level::from_str(c.log_level) == spdlog::level::off && c.log_level != "off") {
    throw InvalidInput("log_level", "\"" + c.log_level +
                                        "\" is not one of trace, debug, info, warn, error, off");
  }
  require_in_range("status_interval_s", c.status_interval_s, 0.01, 3600.0);
  require_in_range("stats_log_interval_s", c.stats_log_interval_s, 0.1, 86400.0);
  require_in_range("liveliness_lease_s", c.liveliness_lease_s, 0.1, 3600.0);
  require_in_range("reply_match_timeout_s", c.reply_match_timeout_s, 0.0, 60.0);
  require_in_range("shutdown_grace_s", c.shutdown_grace_s, 0.0, 60.0);
  require_in_range("reply_block_s", c.reply_block_s, 0.001, 60.0);
  require_in_range("departed_hold_s", c.departed_hold_s, 0.0, 3600.0);
  // Down to a microsecond so a test can make any computing request miss it; up to a minute,
  // past which a client has long given up (rule 8 of docs/protocol.md).
  require_in_range("calculation_deadline_s", c.calculation_deadline_s, 1e-6, 60.0);
}

std::string service_usage() {
  ServiceCommand command;
  CLI::App app{"gearcoupling-service: crowned-tooth gear coupling calculations over DDS "
               "request/reply",
               "gearcoupling-service"};
  declare_flags(app, command);
  return app.help();
}

std::string service_bash_completion() {
  ServiceCommand command;
  CLI::App app;
  declare_flags(app, command);
  std::string flags = "--help";
  for (const CLI::Option* option : app.get_options()) {
    if (!option->get_lnames().empty() && option->get_lnames().front() != "help") {
      flags += " --" + option->get_lnames().front();
    }
  }
  return R"(# bash completion for gearcoupling-service; written by `gearcoupling-service --bash-completion`
# from the flag declarations of its parser.
_gearcoupling_service() {
  local cur="${COMP_WORDS[COMP_CWORD]}" prev="${COMP_WORDS[COMP_CWORD-1]}"
  case "$prev" in
    --config|--catalogue) COMPREPLY=($(compgen -f -- "$cur")); return ;;
    --log-level) COMPREPLY=($(compgen -W "trace debug info warn error off" -- "$cur")); return ;;
  esac
  COMPREPLY=($(compgen -W ")" + flags + R"(" -- "$cur"))
}
complete -o filenames -F _gearcoupling_service gearcoupling-service
)";
}

std::string service_version() { return "gearcoupling-service " GC_VERSION "\n"; }

}  // namespace gc::service
