#!/usr/bin/env bash
# What a team changes in the example `fastddsgen -example CMake <file>.idl` generates, to talk to
# plumb (docs/transports.md, "Talking to plumb without plumb"). Nothing else in it is touched.
#   1. the topic name: plumb's, not "<file>Topic";
#   2. the domain id: plumb's (here from the environment variable PLUMB_DOMAIN_ID, as plumb's own);
#   3. the participant QoS from the XML profile (share/plumb/config/fastdds-*.xml, named by
#      FASTRTPS_DEFAULT_PROFILES_FILE): the generated code builds a fresh DomainParticipantQos,
#      which ignores every profile, and so announces itself on the external interfaces only and
#      never meets plumb's loopback participants.
# Test-only additions: the subscriber prints the inclination it got; the publisher fills its sensor
# batch from fill_batch.inc (a team fills it from its sensors).
# usage: adapt_fastddsgen.sh DIR NAME TOPIC   (NAME: attitude or sensor, the generated files' stem)
set -euo pipefail
dir=$1 name=$2 topic=$3
for f in "$dir/${name}Publisher.cxx" "$dir/${name}Subscriber.cxx"; do
  sed -i \
    -e "s|\"${name}Topic\"|\"${topic}\"|" \
    -e 's|DomainParticipantQos pqos;|DomainParticipantFactory::get_instance()->load_profiles();\n    DomainParticipantQos pqos = DomainParticipantFactory::get_instance()->get_default_participant_qos();|' \
    -e 's|create_participant(0, pqos)|create_participant(std::getenv("PLUMB_DOMAIN_ID") ? std::atoi(std::getenv("PLUMB_DOMAIN_ID")) : 0, pqos)|' \
    -e 's|#include <fastdds/dds/domain/DomainParticipantFactory.hpp>|#include <fastdds/dds/domain/DomainParticipantFactory.hpp>\n#include <cstdlib>|' "$f"
  grep -q "\"${topic}\"" "$f" && grep -q "get_default_participant_qos" "$f" && grep -q 'getenv("PLUMB_DOMAIN_ID")' "$f" ||
    { echo "adapt_fastddsgen.sh: $f does not look like fastddsgen's example any more" >&2; exit 1; }
done
if [ "$name" = attitude ]; then
  sed -i 's|std::cout << "Sample received, count=" << samples << std::endl;|std::cout << "Sample received, count=" << samples << " inclination_deg=" << st.inclination_deg() << std::endl;|' \
    "$dir/${name}Subscriber.cxx"
fi
if [ "$name" = sensor ]; then
  here=$(cd "$(dirname "$0")" && pwd)
  sed -i -e "s|#include <thread>|#include <thread>\n#include \"$here/fill_batch.inc\"|" \
         -e 's|writer_->write(&st);|fill_batch(st, msgsent);\n            writer_->write(\&st);|' "$dir/sensorPublisher.cxx"
  grep -q "fill_batch(st" "$dir/sensorPublisher.cxx" || { echo "adapt_fastddsgen.sh: no write() in the publisher" >&2; exit 1; }
fi
