#include "qos.hpp"

namespace plumb::transport::cyclonedds {

QosPtr make_endpoint_qos(const Qos& qos) {
  QosPtr q(dds_create_qos());
  // A reliable writer whose readers fall behind blocks at most this long before write() fails.
  dds_qset_reliability(q.get(), qos.reliability == Reliability::Reliable ? DDS_RELIABILITY_RELIABLE
                                                                           : DDS_RELIABILITY_BEST_EFFORT,
                       DDS_SECS(1));
  dds_qset_durability(q.get(), qos.durability == Durability::TransientLocal ? DDS_DURABILITY_TRANSIENT_LOCAL
                                                                              : DDS_DURABILITY_VOLATILE);
  dds_qset_history(q.get(), qos.history == History::KeepAll ? DDS_HISTORY_KEEP_ALL : DDS_HISTORY_KEEP_LAST,
                   qos.depth > 0 ? qos.depth : 1);
  // What a transient-local writer keeps for late joiners is Cyclone's durability-service history,
  // KEEP_LAST 1 by default whatever the writer's own history: without this a keep-all topic (the
  // survey) would give a late joiner its last sample only.
  if (qos.durability == Durability::TransientLocal)
    dds_qset_durability_service(q.get(), 0, qos.history == History::KeepAll ? DDS_HISTORY_KEEP_ALL : DDS_HISTORY_KEEP_LAST,
                                qos.depth > 0 ? qos.depth : 1, DDS_LENGTH_UNLIMITED, DDS_LENGTH_UNLIMITED,
                                DDS_LENGTH_UNLIMITED);
  // Cyclone 0.10 would pick XCDR2 for some types; Fast DDS 2.9 only reads XCDR1 (docs/architecture.md).
  const dds_data_representation_id_t xcdr1[] = {DDS_DATA_REPRESENTATION_XCDR1};
  dds_qset_data_representation(q.get(), 1, xcdr1);
  return q;
}

}  // namespace plumb::transport::cyclonedds
