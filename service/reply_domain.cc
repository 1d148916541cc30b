#include "service/reply_domain.h"

#include <malloc.h>

#include <atomic>
#include <string>

#include "protocol/topics.h"

namespace gc::service {

using protocol::check_dds;
using protocol::Entity;

namespace {

/// Local ids of reply domains: above every DDS domain id (0-232, the RTPS port mapping), never
/// used twice in a process (Cyclone refuses a second domain with a live one's id).
std::atomic<dds_domainid_t> next_local_id{1000};

/// `dds`'s configuration, plus ExternalDomainId: the same interfaces, peers, security and tuning
/// as the service's participant, on the network as domain `domain`.
std::string reply_domain_config(int domain, const protocol::DdsConfig& dds) {
  std::string config = dds.uri;
  if (!config.empty()) config += ',';
  config += "<Discovery><ExternalDomainId>" + std::to_string(domain) +
            "</ExternalDomainId></Discovery>";
  return config;
}

}  // namespace

ReplyDomain::ReplyDomain(int domain, const protocol::DdsConfig& dds) {
  const dds_domainid_t local_id = next_local_id++;
  const std::string config = reply_domain_config(domain, dds);
  domain_ = Entity(check_dds(dds_create_domain(local_id, config.c_str()), "dds_create_domain(replies)"));
  participant_ = Entity(check_dds(dds_create_participant(local_id, nullptr, nullptr),
                                  "dds_create_participant(replies)"));
  reply_topics_ = protocol::make_reply_topics(participant_.get());
}

ReplyDomain::~ReplyDomain() {
  for (Entity& topic : reply_topics_) topic.reset();
  participant_.reset();
  domain_.reset();
  malloc_trim(0);
}

}  // namespace gc::service
