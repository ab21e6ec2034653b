#include "scene/StrictJson.h"

#include <string>
#include <unordered_set>
#include <vector>

#include "scene/AssetFiles.h"
#include "scene/JsonNode.h"

namespace specula::scene {

namespace {

// Where the parser is: one frame per open container, enough to name the path of the next value.
struct Frame {
  std::string path;
  bool isArray = false;
  std::size_t nextIndex = 0;
  std::string key;
  std::unordered_set<std::string> keys;
};

}  // namespace

Result<nlohmann::json> parseStrictJson(std::string_view text) {
  using Event = nlohmann::json::parse_event_t;
  std::vector<Frame> open;
  const auto nextPath = [&open] {
    if (open.empty()) return std::string("$");
    const Frame& frame = open.back();
    return frame.isArray ? frame.path + "[" + std::to_string(frame.nextIndex) + "]"
                         : frame.path + JsonNode::keyStep(frame.key);
  };
  const auto valueDone = [&open] {
    if (!open.empty() && open.back().isArray) ++open.back().nextIndex;
  };
  const nlohmann::json::parser_callback_t check = [&](int, Event event, nlohmann::json& parsed) {
    switch (event) {
      case Event::object_start:
      case Event::array_start:
        // Named by the outermost container below the root: the full path would be as deep as the nesting.
        if (open.size() >= kMaxJsonDepth)
          throw JsonNode::Failure{open[1].path + ": nested deeper than " + std::to_string(kMaxJsonDepth) + " levels"};
        open.push_back(Frame{nextPath(), event == Event::array_start, 0, {}, {}});
        break;
      case Event::key:
        open.back().key = parsed.get<std::string>();
        if (!open.back().keys.insert(open.back().key).second)
          throw JsonNode::Failure{nextPath() + ": duplicate key; each key may appear once per object"};
        break;
      case Event::object_end:
      case Event::array_end:
        open.pop_back();
        valueDone();
        break;
      case Event::value: valueDone(); break;
    }
    return true;
  };
  try {
    return nlohmann::json::parse(text.begin(), text.end(), check);
  } catch (const JsonNode::Failure& failure) {
    return Error{failure.message};
  } catch (const nlohmann::json::out_of_range&) {
    // nlohmann refuses numbers beyond double range (1e999) before the callback sees them.
    return Error{nextPath() + ": number out of range (numbers must be finite)"};
  } catch (const nlohmann::json::exception& error) {
    // Drop nlohmann's "[json.exception.parse_error.101] " prefix; the rest gives line and column.
    const std::string what = oneLine(error.what());
    const std::size_t start = what.find("] ");
    return Error{"invalid JSON: " + (start == std::string::npos ? what : what.substr(start + 2))};
  }
}

}  // namespace specula::scene
