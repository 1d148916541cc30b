#include "service/reply_domain.h"

#include <malloc.h>

#include <string>

#include "protocol/topics.h"

namespace gc::service {

using protocol::check_dds;
using protocol::Entity;

namespace {

/// Local ids of reply domains are taken from this one down, skipping the service's own and those
/// in use (Cyclone refuses a second domain with a live one's id). Cyclone's access control checks
/// a participant's local domain id, not the one on the wire, against the governance and
/// permissions documents, which take ids 0-230 (docs/security.md): so the top of that range.
constexpr dds_domainid_t kHighestLocalId = 230;

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
  const std::string config = reply_domain_config(domain, dds);
  dds_domainid_t local_id = kHighestLocalId + 1;
  dds_entity_t created = DDS_RETCODE_PRECONDITION_NOT_MET;
  while (created == DDS_RETCODE_PRECONDITION_NOT_MET && local_id-- > 0) {
    if (local_id != static_cast<dds_domainid_t>(domain)) {
      created = dds_create_domain(local_id, config.c_str());
    }
  }
  domain_ = Entity(check_dds(created, "dds_create_domain(replies)"));
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
