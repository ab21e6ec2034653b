#include "ProtocolCodec.h"

#include <google/protobuf/util/json_util.h>

namespace specula::protocol {

namespace {

namespace protobuf = google::protobuf;

// Proto3 keeps fields it does not know; for a strict protocol they mean a wrong or garbled message.
bool hasUnknownFields(const protobuf::Message& message) {
  const protobuf::Reflection* reflection = message.GetReflection();
  if (!reflection->GetUnknownFields(message).empty()) return true;
  std::vector<const protobuf::FieldDescriptor*> fields;
  reflection->ListFields(message, &fields);
  for (const protobuf::FieldDescriptor* field : fields) {
    if (field->cpp_type() != protobuf::FieldDescriptor::CPPTYPE_MESSAGE) continue;
    if (field->is_repeated()) {
      for (int i = 0; i < reflection->FieldSize(message, field); ++i)
        if (hasUnknownFields(reflection->GetRepeatedMessage(message, field, i))) return true;
    } else if (hasUnknownFields(reflection->GetMessage(message, field))) {
      return true;
    }
  }
  return false;
}

template <class Message>
Result<Message> decode(std::string_view payload, Encoding encoding) {
  Message message;
  if (encoding == Encoding::Json) {
    protobuf::util::JsonParseOptions options;
    options.ignore_unknown_fields = false;
    const auto status = protobuf::util::JsonStringToMessage(std::string(payload), &message, options);
    if (!status.ok()) return Error{"not a valid specula.v1 JSON message: " + status.ToString()};
    return message;
  }
  if (!message.ParseFromArray(payload.data(), static_cast<int>(payload.size())))
    return Error{"not a valid specula.v1 protobuf message (truncated or garbled bytes)"};
  if (hasUnknownFields(message)) return Error{"the protobuf message has fields specula.v1 does not define"};
  return message;
}

template <class Message>
std::string encode(const Message& message, Encoding encoding) {
  std::string out;
  if (encoding == Encoding::Json) {
    protobuf::util::JsonPrintOptions options;
    options.always_print_primitive_fields = true;  // scripts read every field without defaults logic
    (void)protobuf::util::MessageToJsonString(message, &out, options);  // cannot fail for our own messages
  } else {
    message.SerializeToString(&out);
  }
  return out;
}

}  // namespace

Result<v1::ClientMessage> decodeClientMessage(std::string_view payload, bool text, Encoding encoding) {
  if (encoding == Encoding::Json && !text)
    return Error{"this connection speaks specula.v1.json: send text messages, not binary"};
  if (encoding == Encoding::Proto && text)
    return Error{"this connection speaks specula.v1.proto: send binary messages, not text"};
  auto message = decode<v1::ClientMessage>(payload, encoding);
  if (message && message->kind_case() == v1::ClientMessage::KIND_NOT_SET)
    return Error{"the message sets none of hello, camera, animation, settings, resize, statsRequest"};
  return message;
}

std::string encodeServerMessage(const v1::ServerMessage& message, Encoding encoding) {
  return encode(message, encoding);
}

std::string encodeClientMessage(const v1::ClientMessage& message, Encoding encoding) {
  return encode(message, encoding);
}

Result<v1::ServerMessage> decodeServerMessage(std::string_view payload, Encoding encoding) {
  return decode<v1::ServerMessage>(payload, encoding);
}

}  // namespace specula::protocol
