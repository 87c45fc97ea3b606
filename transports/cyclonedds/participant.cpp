#include "participant.hpp"

#include <algorithm>
#include <map>
#include <mutex>
#include <string_view>
#include <vector>

#include "check.hpp"
#include "domain_config.hpp"
#include "endpoints.hpp"
#include "entity.hpp"
#include "security.hpp"

namespace plumb::transport::cyclonedds {

namespace {

constexpr int kMaxDomainId = 232;
constexpr std::string_view kCycloneBuiltinPrefix = "org::eclipse::cyclonedds::builtin::";  // the RTPS port mapping runs out of UDP ports above this

// One Cyclone domain (its configuration, threads and sockets) per domain id and process, shared
// by the participants on it and deleted with the last of them. Cyclone allows one explicitly
// configured domain per id, hence the process-wide registry.
class Domain {
 public:
  Domain(int id, std::string interface) : id_(id), interface_(std::move(interface)) {
    const std::string config = domain_config(interface_);
    const dds_entity_t handle = dds_create_domain(static_cast<dds_domainid_t>(id_), config.c_str());
    check(handle, "cannot start Cyclone DDS on domain " + std::to_string(id_) +
                      (interface_.empty() ? std::string(" (loopback)") : " on interface '" + interface_ + "'"));
    handle_ = Entity(handle);
  }
  int id() const { return id_; }
  const std::string& interface() const { return interface_; }

 private:
  int id_;
  std::string interface_;
  Entity handle_;
};

// Never destroyed: a participant may outlive static destruction (a global in a component), and
// its Domain's deleter still needs the lock.
std::mutex& g_domains_mutex = *new std::mutex;
std::map<int, std::weak_ptr<Domain>>& g_domains = *new std::map<int, std::weak_ptr<Domain>>;

std::shared_ptr<Domain> acquire_domain(int id, const std::string& interface) {
  const std::lock_guard lock(g_domains_mutex);
  if (auto existing = g_domains[id].lock()) {
    if (existing->interface() != interface) {
      throw Error("domain " + std::to_string(id) + " already runs on interface '" + existing->interface() +
                  "' in this process, cannot also use '" + interface + "'");
    }
    return existing;
  }
  // The deleter takes the lock so that a new Domain for the same id is never created while the
  // old one is still being torn down (Cyclone would refuse it).
  auto domain = std::shared_ptr<Domain>(new Domain(id, interface), [](Domain* d) {
    const std::lock_guard lock(g_domains_mutex);
    delete d;
  });
  g_domains[id] = domain;
  return domain;
}

struct BuiltinEndpoint {
  std::string topic;
  std::string type;
};

// Alive discovered endpoints of one built-in topic (DCPSPublication or DCPSSubscription).
std::vector<BuiltinEndpoint> alive_endpoints(dds_entity_t builtin_reader) {
  constexpr std::size_t kMaxEndpoints = 4096;
  std::vector<void*> samples(kMaxEndpoints, nullptr);
  std::vector<dds_sample_info_t> infos(kMaxEndpoints);
  const dds_return_t n = dds_read_mask(builtin_reader, samples.data(), infos.data(), kMaxEndpoints, kMaxEndpoints,
                                       DDS_ANY_SAMPLE_STATE | DDS_ANY_VIEW_STATE | DDS_ALIVE_INSTANCE_STATE);
  check(n, "cannot read discovered endpoints");
  std::vector<BuiltinEndpoint> result;
  for (dds_return_t i = 0; i < n; ++i) {
    if (!infos[i].valid_data) continue;
    const auto* endpoint = static_cast<const dds_builtintopic_endpoint_t*>(samples[i]);
    // Cyclone lists its own built-in readers (the two we use here) as ordinary endpoints.
    if (endpoint->type_name && std::string_view(endpoint->type_name).starts_with(kCycloneBuiltinPrefix)) continue;
    result.push_back({endpoint->topic_name ? endpoint->topic_name : "", endpoint->type_name ? endpoint->type_name : ""});
  }
  dds_return_loan(builtin_reader, samples.data(), n);
  return result;
}

class CycloneParticipant final : public Participant {
 public:
  explicit CycloneParticipant(const ParticipantOptions& options)
      : domain_(acquire_domain(options.domain_id, options.interface)) {
    dds_qos_t* qos = dds_create_qos();
    dds_qset_entity_name(qos, options.name.c_str());  // shows in discovery (ddsls, Fast DDS monitor)
    if (!options.security.empty()) {
      try {
        add_security(qos, check_security_files(options.security));
      } catch (...) {
        dds_delete_qos(qos);
        throw;
      }
    }
    const dds_entity_t handle = dds_create_participant(static_cast<dds_domainid_t>(options.domain_id), qos, nullptr);
    dds_delete_qos(qos);
    check(handle, "cannot create a participant on domain " + std::to_string(options.domain_id) +
                      (options.security.empty() ? std::string() : " with the security of " + options.security));
    participant_ = Entity(handle);
    // Created now so that they collect every endpoint discovered from here on.
    publications_ = Entity(check(dds_create_reader(participant_.get(), DDS_BUILTIN_TOPIC_DCPSPUBLICATION, nullptr, nullptr),
                                 "cannot read discovered publications"));
    subscriptions_ = Entity(check(dds_create_reader(participant_.get(), DDS_BUILTIN_TOPIC_DCPSSUBSCRIPTION, nullptr, nullptr),
                                  "cannot read discovered subscriptions"));
  }

  std::unique_ptr<RawWriter> create_writer(const TypeSupport& type, const std::string& topic, const Qos& qos) override {
    return make_writer(participant_.get(), type, topic, qos);
  }

  std::unique_ptr<RawReader> create_reader(const TypeSupport& type, const std::string& topic, const Qos& qos,
                                           std::function<void()> on_data) override {
    return make_reader(participant_.get(), type, topic, qos, std::move(on_data));
  }

  std::vector<DiscoveredTopic> discovered_topics() override {
    std::map<std::pair<std::string, std::string>, DiscoveredTopic> topics;
    auto entry = [&](const BuiltinEndpoint& e) -> DiscoveredTopic& {
      auto& t = topics[{e.topic, e.type}];
      t.name = e.topic;
      t.type_name = e.type;
      return t;
    };
    for (const auto& e : alive_endpoints(publications_.get())) ++entry(e).writers;
    for (const auto& e : alive_endpoints(subscriptions_.get())) ++entry(e).readers;
    std::vector<DiscoveredTopic> result;
    for (auto& [key, topic] : topics) result.push_back(std::move(topic));
    return result;
  }

 private:
  std::shared_ptr<Domain> domain_;  // declared first: outlives the participant
  Entity participant_;
  Entity publications_;
  Entity subscriptions_;
};

}  // namespace

std::unique_ptr<Participant> make_participant(const ParticipantOptions& options) {
  if (options.domain_id < 0 || options.domain_id > kMaxDomainId) {
    throw Error("domain id " + std::to_string(options.domain_id) + " is out of range 0.." +
                std::to_string(kMaxDomainId));
  }
  return std::make_unique<CycloneParticipant>(options);
}

}  // namespace plumb::transport::cyclonedds
