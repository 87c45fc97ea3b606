// What differs between topic types on Fast DDS, behind one interface so that the writer, reader and
// participant code is written once: the TypeSupport fastddsgen generates, and a codec that owns one
// sample of fastddsgen's class and converts through it on write and take. The entries are generated
// from idl/ at build time (idl/generate/emit_fastdds.py).
#pragma once

#include <fastdds/dds/core/LoanableSequence.hpp>
#include <fastdds/dds/publisher/DataWriter.hpp>
#include <fastdds/dds/subscriber/DataReader.hpp>
#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <fastdds/dds/topic/Topic.hpp>
#include <fastdds/dds/topic/TopicDataType.hpp>
#include <fastdds/dds/topic/TypeSupport.hpp>

#include <algorithm>
#include <climits>
#include <memory>
#include <span>

#include "plumb/transport/transport.hpp"

namespace plumb::transport::fastdds {

class SampleCodec {
 public:
  virtual ~SampleCodec() = default;
  // Converts the topics:: message at `message` and writes it; throws Error if it cannot be sent.
  virtual void write(eprosima::fastdds::dds::DataWriter& writer, const void* message) = 0;
  // Takes the next valid sample (skipping disposal/unregistration notices) into `message`.
  virtual bool take(eprosima::fastdds::dds::DataReader& reader, void* message) = 0;
  // Takes up to `max` valid samples (see RawReader::take(max, target)).
  virtual std::size_t take(eprosima::fastdds::dds::DataReader& reader, std::size_t max, TakeTarget target) = 0;
};

template <class Plumb, class Fast, void (*ToFast)(const Plumb&, Fast&), void (*FromFast)(const Fast&, Plumb&)>
class Codec final : public SampleCodec {
 public:
  void write(eprosima::fastdds::dds::DataWriter& writer, const void* message) override {
    ToFast(*static_cast<const Plumb*>(message), sample_);
    if (!writer.write(&sample_)) {
      throw Error("Fast DDS refused to write on topic " + writer.get_topic()->get_name());
    }
  }

  bool take(eprosima::fastdds::dds::DataReader& reader, void* message) override {
    eprosima::fastdds::dds::SampleInfo info;
    while (reader.take_next_sample(&sample_, &info) == ReturnCode_t::RETCODE_OK) {
      if (info.valid_data) {
        FromFast(sample_, *static_cast<Plumb*>(message));
        return true;
      }
    }
    return false;
  }

  // One DataReader::take per call into sequences this codec owns (kept from call to call, so no
  // allocation per call): Fast DDS deserializes into them and each is converted into the target.
  // Not loaned: with loans, Fast DDS 2.9 crashed in DataReaderImpl::read_or_take when the take ran in
  // the data callback while fragmented samples (a SensorBatch from Cyclone DDS) were being assembled.
  std::size_t take(eprosima::fastdds::dds::DataReader& reader, std::size_t max, TakeTarget target) override {
    using size_type = eprosima::fastdds::dds::LoanableCollection::size_type;
    std::size_t filled = 0;
    while (filled < max) {
      const auto wanted = static_cast<size_type>(std::min<std::size_t>(max - filled, kSamplesPerTake));
      if (samples_.maximum() < wanted) {
        samples_.length(wanted);  // owned: allocates the elements once
        infos_.length(wanted);
      }
      // Fast DDS appends after the current length of an owned sequence: start from empty.
      samples_.length(0);
      infos_.length(0);
      if (reader.take(samples_, infos_, wanted) != ReturnCode_t::RETCODE_OK) break;  // RETCODE_NO_DATA: empty
      const size_type n = samples_.length();
      for (size_type i = 0; i < n; ++i) {
        if (infos_[i].valid_data) FromFast(samples_[i], *static_cast<Plumb*>(target.slot(target.context, filled++)));
      }
      if (n < wanted) break;
    }
    return filled;
  }

 private:
  static constexpr std::size_t kSamplesPerTake = 64;
  Fast sample_;  // reused: the generated classes allocate their sequences once
  eprosima::fastdds::dds::LoanableSequence<Fast> samples_;  // owned, for the batched take
  eprosima::fastdds::dds::SampleInfoSeq infos_;
};

struct FastTypeSupport {
  const TypeSupport* type;
  eprosima::fastdds::dds::TopicDataType* (*make_data_type)();  // fastddsgen's <Type>PubSubType
  std::unique_ptr<SampleCodec> (*make_codec)();
};

// Every struct of idl/ (generated).
std::span<const FastTypeSupport* const> generated_types();

// The entry of `type`; Error when this plugin was built from IDL without it, or with another layout.
const FastTypeSupport& find_type(const TypeSupport& type);

}  // namespace plumb::transport::fastdds
