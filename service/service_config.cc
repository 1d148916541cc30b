#include "service/service_config.h"

#include <charconv>
#include <fstream>
#include <sstream>

#include <google/protobuf/io/tokenizer.h>
#include <google/protobuf/text_format.h>
#include <spdlog/common.h>

#include "core/model_error.h"
#include "service/service_config.pb.h"

namespace gc::service {
namespace {

class FileErrors : public google::protobuf::io::ErrorCollector {
 public:
  explicit FileErrors(std::string path) : path_(std::move(path)) {}
  void AddError(int line, int column, const std::string& message) override {
    if (first_.empty()) {
      first_ = path_ + ":" + std::to_string(line + 1) + ":" + std::to_string(column + 1) + ": " +
               message;
    }
  }
  const std::string& first() const { return first_; }

 private:
  std::string path_;
  std::string first_;
};

double parse_number(const std::string& flag, const std::string& text) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) {
    throw InvalidInput(flag, "\"" + text + "\" is not a number");
  }
  return value;
}

int parse_integer(const std::string& flag, const std::string& text) {
  int value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) {
    throw InvalidInput(flag, "\"" + text + "\" is not a whole number");
  }
  return value;
}

}  // namespace

void apply_config_file(const std::string& path, ServiceConfig& config) {
  std::ifstream in(path);
  if (!in) throw InvalidInput("--config", "cannot read \"" + path + "\"");
  std::stringstream text;
  text << in.rdbuf();
  gearcoupling::v1::ServiceConfig file;
  google::protobuf::TextFormat::Parser parser;
  FileErrors errors(path);
  parser.RecordErrorsTo(&errors);
  if (!parser.ParseFromString(text.str(), &file)) throw InvalidInput("--config", errors.first());
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

ServiceCommand parse_service_command(const std::vector<std::string>& args) {
  ServiceCommand command;
  // The file first, so flags override it wherever --config appears.
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--config") {
      if (i + 1 >= args.size()) throw InvalidInput("--config", "needs a file");
      apply_config_file(args[i + 1], command.config);
    }
  }
  ServiceConfig& c = command.config;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& flag = args[i];
    if (flag == "--help" || flag == "-h") {
      command.help = true;
      continue;
    }
    if (i + 1 >= args.size()) throw InvalidInput(flag, "unknown flag or missing value");
    const std::string& value = args[++i];
    if (flag == "--config") continue;
    if (flag == "--domain") {
      c.domain = parse_integer(flag, value);
    } else if (flag == "--threads") {
      const int threads = parse_integer(flag, value);
      if (threads < 0) throw InvalidInput(flag, threads, "[0, 1024]; 0 = one per core");
      c.threads = static_cast<unsigned>(threads);
    } else if (flag == "--catalogue" || flag == "--catalog") {
      c.catalogue_dir = value;
    } else if (flag == "--log-level") {
      c.log_level = value;
    } else if (flag == "--status-interval") {
      c.status_interval_s = parse_number(flag, value);
    } else if (flag == "--stats-interval") {
      c.stats_log_interval_s = parse_number(flag, value);
    } else if (flag == "--lease") {
      c.liveliness_lease_s = parse_number(flag, value);
    } else if (flag == "--reply-match-timeout") {
      c.reply_match_timeout_s = parse_number(flag, value);
    } else if (flag == "--reply-block") {
      c.reply_block_s = parse_number(flag, value);
    } else if (flag == "--departed-hold") {
      c.departed_hold_s = parse_number(flag, value);
    } else if (flag == "--shutdown-grace") {
      c.shutdown_grace_s = parse_number(flag, value);
    } else if (flag == "--deadline") {
      c.calculation_deadline_s = parse_number(flag, value);
    } else {
      throw InvalidInput(flag, "unknown flag (see --help)");
    }
  }
  validate(c);
  return command;
}

void validate(const ServiceConfig& c) {
  if (c.domain < 0 || c.domain > 232) throw InvalidInput("domain", c.domain, "[0, 232]");
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
  return R"(gearcoupling-service: crowned-tooth gear coupling calculations over DDS request/reply

usage: gearcoupling-service [--config FILE] [--domain N] [--threads N] [--catalogue DIR]
                            [--log-level LEVEL] [--status-interval S] [--stats-interval S]
                            [--lease S] [--reply-match-timeout S] [--reply-block S]
                            [--departed-hold S] [--shutdown-grace S] [--deadline S]

  --config FILE          settings in protobuf text format (service/service_config.proto);
                         flags override it
  --domain N             DDS domain id, 0..232 (default 0); the network comes from the Cyclone
                         XML named by CYCLONEDDS_URI (deploy/cyclonedds-loopback.xml)
  --threads N            worker threads, 0 = one per core (default 0)
  --catalogue DIR        directory of *.textproto couplings (default: the bundled NREL ones or
                         $GEARCOUPLING_CATALOG)
  --log-level LEVEL      trace, debug (one line per request), info (default), warn, error, off
  --status-interval S    status topic period in seconds (default 1)
  --stats-interval S     periodic stats log line in seconds (default 10)
  --lease S              liveliness lease of the status writer in seconds (default 2)
  --reply-match-timeout S  longest a request waits (parked, before any work) for its
                         client's reply reader, then it is dropped (default 1)
  --reply-block S        longest a reply waits, retried without blocking a worker, for a
                         client that does not acknowledge (slow, stopped, killed) (default 0.5)
  --departed-hold S      then drop that client's requests for this long (default 5)
  --shutdown-grace S     after SIGINT/SIGTERM keep answering this long, then exit (default 0.2)
  --deadline S           a request not answered this long after it arrived (queued or
                         computing) gets STATUS_DEADLINE_EXCEEDED, 1e-6..60 (default 1)
)";
}

}  // namespace gc::service
