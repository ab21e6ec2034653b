// The streaming service end to end on loopback: real Beast server, real WebSocket clients, fake renderer.
#include <turbojpeg.h>

#include <algorithm>

#include "LoadRun.h"
#include "ServerRig.h"

namespace specula::testing {
namespace {

bool antiAliased(const v1::Frame& frame) {
  return std::any_of(frame.stages().begin(), frame.stages().end(),
                     [](const v1::StageTime& stage) { return stage.name() == "anti-aliasing"; });
}

using protocol::Encoding;

// Decodes a frame's JPEG and returns its mean grey level, or -1 when it does not decode to w×h.
double meanGrey(const v1::Frame& frame) {
  tjhandle handle = tjInitDecompress();
  int width = 0, height = 0, subsampling = 0, colourspace = 0;
  const auto* bytes = reinterpret_cast<const unsigned char*>(frame.jpeg().data());
  double mean = -1.0;
  if (tjDecompressHeader3(handle, bytes, static_cast<unsigned long>(frame.jpeg().size()), &width, &height, &subsampling,
                          &colourspace) == 0 &&
      width == static_cast<int>(frame.width()) && height == static_cast<int>(frame.height())) {
    std::vector<unsigned char> grey(static_cast<std::size_t>(width * height));
    if (tjDecompress2(handle, bytes, static_cast<unsigned long>(frame.jpeg().size()), grey.data(), width, 0, height,
                      TJPF_GRAY, 0) == 0) {
      double sum = 0.0;
      for (unsigned char g : grey) sum += g;
      mean = sum / static_cast<double>(grey.size());
    }
  }
  tjDestroy(handle);
  return mean;
}

class StreamingServer : public ::testing::TestWithParam<Encoding> {};

TEST_P(StreamingServer, TheWelcomeNamesWhatTheScenesFilesHeldThatWasNotRead) {
  RigOptions options = defaultRigOptions();
  options.sceneNotes = {"2 animations not played", "extension KHR_materials_clearcoat is not read"};
  ServerRig rig(options);
  auto client = rig.connect(GetParam());
  ASSERT_TRUE(client);
  const v1::Welcome welcome = greet(*client, 80, 60);
  ASSERT_EQ(welcome.scene().notes_size(), 2);
  EXPECT_EQ(welcome.scene().notes(0), "2 animations not played");
  EXPECT_EQ(welcome.scene().notes(1), "extension KHR_materials_clearcoat is not read");
}

TEST_P(StreamingServer, HandshakeWelcomesAndSendsAFirstStillFrame) {
  ServerRig rig;
  auto client = rig.connect(GetParam());
  ASSERT_TRUE(client);
  const v1::Welcome welcome = greet(*client, 80, 60);
  EXPECT_EQ(welcome.protocol_version(), 1u);
  EXPECT_EQ(welcome.session_id().size(), 32u);
  EXPECT_EQ(welcome.resume_token().size(), 32u);
  EXPECT_EQ(welcome.scene().name(), "checker-sphere");
  EXPECT_EQ(welcome.limits().max_message_bytes(), 64u * 1024u);
  EXPECT_TRUE(welcome.scene().animated());
  EXPECT_TRUE(welcome.playing()) << "an animated scene starts playing";
  EXPECT_EQ(welcome.settings().tessellation(), v1::TESSELLATION_CRACK_FREE);
  EXPECT_EQ(welcome.settings().plan(), v1::PLAN_NEEDED);
  EXPECT_EQ(welcome.settings().search(), v1::SEARCH_CROSSHAIR) << "the default search";
  auto frame = receiveUntil(*client, isFrame);
  ASSERT_TRUE(frame);
  EXPECT_EQ(frame->frame().width(), 80u);
  EXPECT_EQ(frame->frame().height(), 60u);
  EXPECT_EQ(frame->frame().number(), 1u);
  EXPECT_EQ(frame->frame().search().searched(), 42u);
  EXPECT_TRUE(frame->frame().still());
  EXPECT_EQ(frame->frame().stages(0).name(), "fake");
  EXPECT_TRUE(antiAliased(frame->frame())) << "a still frame takes the default 4 samples";
  EXPECT_EQ(welcome.settings().still_samples(), 4u);
  EXPECT_EQ(welcome.settings().interactive_samples(), 1u);
  EXPECT_GE(meanGrey(frame->frame()), 0.0) << "the frame carries a decodable JPEG of its stated size";
}

TEST_P(StreamingServer, CameraUpdateIsAnsweredByAFrameCarryingItsSequence) {
  ServerRig rig;
  auto client = rig.connect(GetParam());
  ASSERT_TRUE(client);
  greet(*client);
  for (std::uint64_t sequence : {7u, 8u, 30u}) {
    const glm::vec3 eye(static_cast<float>(sequence) / 10.0f, 1.0f, 6.0f);
    ASSERT_TRUE(client->send(cameraMessage(eye, sequence)).ok());
    auto frame = receiveUntil(
        *client, [&](const v1::ServerMessage& m) { return m.has_frame() && m.frame().input_sequence() == sequence; });
    ASSERT_TRUE(frame) << "no frame for sequence " << sequence;
    EXPECT_NEAR(meanGrey(frame->frame()), FakeRenderer::eyeColour(eye), 3.0) << "the frame shows that camera";
    EXPECT_GT(frame->frame().client_time_ms(), 0.0) << "the client's timestamp is echoed";
    EXPECT_GE(frame->frame().server_ms(), 0.0);
  }
}

// A paused view moved once: the interactive frame that answers the move, the renders up to it, and
// the still frame that follows once input stops; then nothing more arrives.
struct MovedOnce {
  std::optional<v1::ServerMessage> interactive, still;
  int rendersBeforeStill = 0;
};

MovedOnce moveOnceAndSettle(ServerRig& rig, client::SpeculaClient& client) {
  MovedOnce moved;
  greet(client);
  EXPECT_TRUE(client.send(animationMessage(v1::AnimationControl::PAUSE)).ok());
  receiveUntil(client, isFrame);
  EXPECT_TRUE(client.send(cameraMessage({1, 1, 6}, 1)).ok());
  moved.interactive =
      receiveUntil(client, [](const v1::ServerMessage& m) { return m.has_frame() && m.frame().input_sequence() == 1; });
  moved.rendersBeforeStill = rig.renders.load();
  moved.still = receiveUntil(client, [](const v1::ServerMessage& m) { return m.has_frame() && m.frame().still(); });
  EXPECT_FALSE(receiveUntil(client, isFrame, 400ms)) << "a still scene sends nothing more";
  return moved;
}

// By default a still frame is anti-aliased (4 samples a pixel) and interactive frames are not: the
// still after input is rendered again, once, with the samples.
TEST_P(StreamingServer, InputGetsInteractiveFramesThenOneAntiAliasedStill) {
  ServerRig rig(defaultRigOptions());
  auto client = rig.connect(GetParam());
  ASSERT_TRUE(client);
  const MovedOnce moved = moveOnceAndSettle(rig, *client);
  ASSERT_TRUE(moved.interactive);
  EXPECT_FALSE(moved.interactive->frame().still());
  EXPECT_FALSE(antiAliased(moved.interactive->frame()));
  ASSERT_TRUE(moved.still) << "a still frame follows once input stops";
  EXPECT_FALSE(moved.still->frame().reencoded()) << "more samples than the interactive frame had: a new render";
  EXPECT_TRUE(antiAliased(moved.still->frame()));
  EXPECT_EQ(rig.renders.load(), moved.rendersBeforeStill + 1)
      << "one render for the still; a paused, unchanged view is not rendered again";
}

// With as many samples for stills as for interactive frames, the still is the last render re-encoded.
TEST_P(StreamingServer, InputGetsInteractiveFramesThenOneFullQualityStill) {
  RigOptions options = defaultRigOptions();
  options.hub.defaults.stillSamples = options.hub.defaults.interactiveSamples;
  ServerRig rig(options);
  auto client = rig.connect(GetParam());
  ASSERT_TRUE(client);
  const MovedOnce moved = moveOnceAndSettle(rig, *client);
  ASSERT_TRUE(moved.interactive);
  EXPECT_FALSE(moved.interactive->frame().still());
  EXPECT_FALSE(moved.interactive->frame().reencoded());
  ASSERT_TRUE(moved.still) << "a still frame follows once input stops";
  EXPECT_EQ(moved.still->frame().input_sequence(), 1u);
  // The view did not change since the interactive frame (paused, same camera and settings): the
  // still is that render encoded again at full quality, not a second render.
  EXPECT_TRUE(moved.still->frame().reencoded());
  EXPECT_EQ(rig.renders.load(), moved.rendersBeforeStill) << "no render for the still, and none after it";
  EXPECT_EQ(moved.still->frame().stages_size(), 0) << "no pass ran for it";
  EXPECT_NEAR(meanGrey(moved.still->frame()), FakeRenderer::eyeColour({1, 1, 6}), 3.0)
      << "it shows the interactive frame's view";
}

TEST_P(StreamingServer, AnimationPlaysPausesAndSeeks) {
  ServerRig rig;
  auto client = rig.connect(GetParam());
  ASSERT_TRUE(client);
  greet(*client);
  ASSERT_TRUE(client->send(animationMessage(v1::AnimationControl::PAUSE)).ok());
  ASSERT_TRUE(client->send(animationMessage(v1::AnimationControl::SEEK, 5000.0)).ok());
  auto seeked = receiveUntil(
      *client, [](const v1::ServerMessage& m) { return m.has_frame() && m.frame().scene_time_ms() == 5000.0; });
  ASSERT_TRUE(seeked) << "a frame at the sought time";
  receiveUntil(*client, [](const v1::ServerMessage& m) { return m.has_frame() && m.frame().still(); });
  EXPECT_FALSE(receiveUntil(*client, isFrame, 400ms)) << "paused and still: no frames";

  ASSERT_TRUE(client->send(animationMessage(v1::AnimationControl::PLAY)).ok());
  std::vector<double> times;
  while (times.size() < 5) {
    auto frame = receiveUntil(*client, isFrame);
    ASSERT_TRUE(frame) << "playing: frames keep coming";
    times.push_back(frame->frame().scene_time_ms());
  }
  EXPECT_GT(times.back(), times.front()) << "scene time advances while playing";
  EXPECT_GE(times.front(), 5000.0);

  ASSERT_TRUE(client->send(animationMessage(v1::AnimationControl::PAUSE)).ok());
  receiveUntil(
      *client, [](const v1::ServerMessage& m) { return m.has_frame() && m.frame().still(); }, 2s);
  EXPECT_FALSE(receiveUntil(*client, isFrame, 400ms)) << "paused again: frames stop";
}

TEST_P(StreamingServer, ResumeTokenRestoresCameraAnimationAndSettings) {
  ServerRig rig;
  std::string token;
  {
    auto client = rig.connect(GetParam());
    ASSERT_TRUE(client);
    token = greet(*client).resume_token();
    ASSERT_TRUE(client->send(animationMessage(v1::AnimationControl::PAUSE)).ok());
    ASSERT_TRUE(client->send(animationMessage(v1::AnimationControl::SEEK, 1234.0)).ok());
    ASSERT_TRUE(client->send(cameraMessage({2, 3, 7}, 5)).ok());
    v1::ClientMessage settings;
    settings.mutable_settings()->set_tessellation(v1::TESSELLATION_PAPER);
    settings.mutable_settings()->set_level(2);
    settings.mutable_settings()->set_jpeg_quality(70);
    settings.mutable_settings()->set_plan(v1::PLAN_EVERYTHING);
    settings.mutable_settings()->set_search(v1::SEARCH_EXPLOSION_MAP_REFINED);
    settings.mutable_settings()->set_explosion_map_size(512);
    settings.mutable_settings()->set_virtual_pixels(v1::PIXELS_AS_PLACED);
    settings.mutable_settings()->set_extrusions(v1::EXTRUSIONS_SEARCH);
    settings.mutable_settings()->set_error_budget_px(-1.0f);  // 0: only exact decisions
    settings.mutable_settings()->set_still_samples(8);
    settings.mutable_settings()->set_interactive_samples(2);
    ASSERT_TRUE(client->send(settings).ok());
    // A frame after the update carries the settings in effect, with what the server implied.
    ASSERT_TRUE(receiveUntil(*client, [](const v1::ServerMessage& m) {
      return m.has_frame() && m.frame().has_settings() && m.frame().settings().ray_cast() == v1::RAY_CAST_NEVER;
    }));
    client->close();
  }
  auto again = rig.connect(GetParam());
  ASSERT_TRUE(again);
  const v1::Welcome welcome = greet(*again, 64, 48, token);
  EXPECT_TRUE(welcome.resumed());
  EXPECT_FLOAT_EQ(welcome.camera().eye().x(), 2.0f);
  EXPECT_FLOAT_EQ(welcome.camera().eye().z(), 7.0f);
  EXPECT_FALSE(welcome.playing());
  EXPECT_DOUBLE_EQ(welcome.scene_time_ms(), 1234.0);
  EXPECT_EQ(welcome.settings().tessellation(), v1::TESSELLATION_PAPER);
  EXPECT_EQ(welcome.settings().level(), 2);
  EXPECT_EQ(welcome.settings().jpeg_quality(), 70u);
  EXPECT_EQ(welcome.settings().plan(), v1::PLAN_EVERYTHING);
  EXPECT_EQ(welcome.settings().search(), v1::SEARCH_EXPLOSION_MAP) << "protocol 1.0's refined map: the map, refined";
  EXPECT_EQ(welcome.settings().explosion_refine(), v1::SWITCH_ON);
  EXPECT_EQ(welcome.settings().explosion_map_size(), 512u);
  EXPECT_EQ(welcome.settings().virtual_pixels(), v1::PIXELS_AS_PLACED);
  EXPECT_EQ(welcome.settings().extrusions(), v1::EXTRUSIONS_SEARCH);
  EXPECT_EQ(welcome.settings().error_budget_px(), -1.0f);
  EXPECT_EQ(welcome.settings().still_samples(), 8u);
  EXPECT_EQ(welcome.settings().interactive_samples(), 2u);
  EXPECT_NE(welcome.resume_token(), token) << "a token resumes once";

  auto third = rig.connect(GetParam());
  EXPECT_FALSE(greet(*third, 64, 48, token).resumed()) << "a used token starts a fresh session";
}

INSTANTIATE_TEST_SUITE_P(BothEncodings, StreamingServer, ::testing::Values(Encoding::Proto, Encoding::Json),
                         [](const auto& test) { return test.param == Encoding::Proto ? "proto" : "json"; });

// ---- hostile and broken input ----

struct BadMessage {
  const char* name;
  Encoding encoding;
  std::string payload;
  bool text;
  int closeCode;
};

std::string truncatedHello() {
  std::string bytes = protocol::encodeClientMessage(helloMessage(), Encoding::Proto);
  return bytes.substr(0, bytes.size() - 3);
}

class BadMessages : public ::testing::TestWithParam<BadMessage> {};

void PrintTo(const BadMessage& bad, std::ostream* out) { *out << bad.name; }

// Pauses the animation and waits for the still frame, so the renderer goes quiet.
void settle(client::SpeculaClient& client) {
  ASSERT_TRUE(client.send(animationMessage(v1::AnimationControl::PAUSE)).ok());
  ASSERT_TRUE(receiveUntil(
      client, [](const v1::ServerMessage& m) { return m.has_frame() && m.frame().still() && m.frame().number() > 1; }));
}

TEST_P(BadMessages, CloseTheConnectionWithTheRightCodeWhileOthersKeepBeingServed) {
  const BadMessage& bad = GetParam();
  ServerRig rig;
  auto bystander = rig.connect(Encoding::Proto);
  ASSERT_TRUE(bystander);
  greet(*bystander);
  settle(*bystander);
  auto offender = rig.connect(bad.encoding);
  ASSERT_TRUE(offender);
  greet(*offender);
  settle(*offender);
  const int rendersBefore = rig.renders.load();
  ASSERT_TRUE(offender->sendRaw(bad.payload, bad.text).ok());
  EXPECT_EQ(closeCodeAfter(*offender), bad.closeCode) << (offender->closeInfo() ? offender->closeInfo()->reason : "");
  std::this_thread::sleep_for(200ms);
  EXPECT_EQ(rig.renders.load(), rendersBefore) << "the bad message never reached the renderer";
  ASSERT_TRUE(bystander->send(cameraMessage({0.5f, 1, 6}, 99)).ok());
  EXPECT_TRUE(receiveUntil(*bystander, [](const v1::ServerMessage& m) {
    return m.has_frame() && m.frame().input_sequence() == 99;
  })) << "the other session is still served";
}

INSTANTIATE_TEST_SUITE_P(
    Hostile, BadMessages,
    ::testing::Values(
        BadMessage{"garbage_proto", Encoding::Proto, std::string("\xff\xff\xff\xff\x0f garbage", 13), false, 1007},
        BadMessage{"truncated_proto", Encoding::Proto, truncatedHello(), false, 1007},
        BadMessage{"text_on_proto", Encoding::Proto, "{\"statsRequest\":{}}", true, 1007},
        BadMessage{"binary_on_json", Encoding::Json, std::string("\x32\x00", 2), false, 1007},
        BadMessage{"garbage_json", Encoding::Json, "{\"camera\": [1,2", true, 1007},
        BadMessage{"unknown_json_field", Encoding::Json, "{\"teleport\":{}}", true, 1007},
        BadMessage{"wrong_json_type", Encoding::Json, "{\"camera\":{\"eye\":\"north\"}}", true, 1007},
        BadMessage{"empty_json_object", Encoding::Json, "{}", true, 1007},
        BadMessage{"second_hello", Encoding::Json, "{\"hello\":{\"protocolVersion\":1,\"width\":8,\"height\":8}}", true,
                   1008},
        BadMessage{"oversized_proto", Encoding::Proto, std::string(70 * 1024, '\x0a'), false, 1009},
        BadMessage{"oversized_json", Encoding::Json, "\"" + std::string(70 * 1024, 'a') + "\"", true, 1009}),
    [](const auto& test) { return std::string(test.param.name); });

TEST(StreamingServerInput, AnythingBeforeHelloClosesWithPolicyViolation) {
  ServerRig rig;
  auto client = rig.connect(Encoding::Proto);
  ASSERT_TRUE(client);
  ASSERT_TRUE(client->send(cameraMessage({0, 1, 5}, 1)).ok());
  auto error = receiveUntil(*client, [](const v1::ServerMessage& m) { return m.has_error(); });
  ASSERT_TRUE(error);
  EXPECT_EQ(error->error().code(), v1::Error::BAD_MESSAGE);
  EXPECT_NE(error->error().message().find("hello"), std::string::npos) << error->error().message();
  EXPECT_EQ(closeCodeAfter(*client), 1008);
}

TEST(StreamingServerInput, OutOfRangeValuesAreRefusedWithAnErrorAndTheSessionGoesOn) {
  ServerRig rig;
  auto client = rig.connect(Encoding::Json);
  ASSERT_TRUE(client);
  greet(*client);
  const std::vector<std::string> refused = {
      R"({"camera":{"eye":{"x":1,"y":1,"z":5},"target":{},"fovDegrees":"NaN","sequence":1}})",
      R"({"camera":{"eye":{"x":0,"y":0,"z":0},"target":{},"sequence":2}})",
      R"({"camera":{"eye":{"x":1e30,"y":0,"z":0},"target":{},"sequence":3}})",
      R"({"resize":{"width":100000,"height":10}})",
      R"({"settings":{"level":99}})",
      R"({"settings":{"plan":7}})",
      R"({"settings":{"search":9}})",
      R"({"settings":{"explosionMapSize":8}})",
      R"({"settings":{"explosionMapSize":100000}})",
      R"({"settings":{"virtualPixels":5}})",
      R"({"settings":{"errorBudgetPx":99}})",
      R"({"settings":{"errorBudgetPx":-0.5}})",
      R"({"settings":{"resolutionScale":"Infinity"}})",
      R"({"settings":{"stillSamples":3}})",
      R"({"settings":{"interactiveSamples":64}})",
      R"({"animation":{"speed":1000}})",
      R"({"animation":{"overrides":[{"object":"no-such-thing"}]}})",
  };
  for (const std::string& message : refused) {
    ASSERT_TRUE(client->sendRaw(message, true).ok());
    auto error = receiveUntil(*client, [](const v1::ServerMessage& m) { return m.has_error(); });
    ASSERT_TRUE(error) << message;
    EXPECT_TRUE(error->error().code() == v1::Error::BAD_VALUE) << message << " → " << error->error().message();
  }
  ASSERT_TRUE(client->send(cameraMessage({1, 1, 6}, 50)).ok());
  EXPECT_TRUE(receiveUntil(
      *client, [](const v1::ServerMessage& m) { return m.has_frame() && m.frame().input_sequence() == 50; }));
}

TEST(StreamingServerInput, ObjectOverridesReplaceTheAnimatedTransform) {
  ServerRig rig;
  auto client = rig.connect(Encoding::Json);
  ASSERT_TRUE(client);
  const v1::Welcome welcome = greet(*client);
  ASSERT_GT(welcome.scene().objects_size(), 0);
  v1::ClientMessage message;
  v1::ObjectTransform& item = *message.mutable_animation()->add_overrides();
  item.set_object(welcome.scene().objects(0));
  item.mutable_translation()->set_y(2.0f);
  message.mutable_animation()->set_sequence(3);
  ASSERT_TRUE(client->send(message).ok());
  EXPECT_TRUE(receiveUntil(
      *client, [](const v1::ServerMessage& m) { return m.has_frame() && m.frame().input_sequence() == 3; }));
}

// ---- limits and failure ----

TEST(StreamingServerLimits, BeyondMaxSessionsAClientIsRefusedClearly) {
  RigOptions options = defaultRigOptions();
  options.hub.maxSessions = 2;
  ServerRig rig(options);
  auto first = rig.connect(), second = rig.connect();
  ASSERT_TRUE(first && second);
  greet(*first);
  greet(*second);
  auto third = rig.connect(Encoding::Json);
  ASSERT_TRUE(third);
  auto error = receiveUntil(*third, [](const v1::ServerMessage& m) { return m.has_error(); });
  ASSERT_TRUE(error);
  EXPECT_EQ(error->error().code(), v1::Error::SERVER_FULL);
  EXPECT_NE(error->error().message().find("--max-sessions"), std::string::npos);
  EXPECT_EQ(closeCodeAfter(*third), 1013);
  first->close();
  for (int i = 0; i < 100 && rig.hub().sessionCount() > 1; ++i) std::this_thread::sleep_for(10ms);
  auto fourth = rig.connect();
  ASSERT_TRUE(fourth);
  EXPECT_FALSE(greet(*fourth).session_id().empty()) << "a freed slot admits the next client";
}

TEST(StreamingServerLimits, AClientThatStopsReadingIsDroppedWithItsSkippedFramesCounted) {
  RigOptions options = defaultRigOptions();
  options.renderer.noise = true;         // incompressible frames fill the socket buffers quickly
  options.server.writeTimeout = 1500ms;  // long enough for newer frames to replace a waiting one first
  ServerRig rig(options);
  auto reader = rig.connect();
  ASSERT_TRUE(reader);
  greet(*reader, 32, 32);
  auto stalled = rig.connect();
  ASSERT_TRUE(stalled);
  greet(*stalled, 1920, 1080);  // from here on it never reads; the animation keeps producing frames
  const auto deadline = std::chrono::steady_clock::now() + 20s;
  while (rig.hub().sessionCount() > 1 && std::chrono::steady_clock::now() < deadline) {
    (void)reader->receive(50ms);
  }
  EXPECT_EQ(rig.hub().sessionCount(), 1u) << "the stalled session was dropped and its memory freed";
  EXPECT_GT(rig.hub().metrics().framesSkipped.load(), 0u) << "frames it could not take were counted";
  EXPECT_EQ(rig.hub().metrics().writeTimeouts.load(), 1u) << "its drop was counted as a write timeout, once";
  EXPECT_TRUE(receiveUntil(*reader, isFrame)) << "the reading client is still served";
  EXPECT_EQ(rig.server().openWebSockets(), 1u);
}

TEST(StreamingServerTiming, AThousandConnectDisconnectCyclesLeaveNothingBehind) {
  ServerRig rig;
  auto cycle = [&](int count) {
    for (int i = 0; i < count; ++i) {
      auto client = rig.connect(i % 2 ? Encoding::Json : Encoding::Proto);
      ASSERT_TRUE(client);
      if (i % 3 != 2) greet(*client, 16, 16);  // every third leaves before hello
      client->close();
    }
  };
  cycle(200);
  const long residentBefore = residentKiB();
  cycle(800);
  for (int i = 0; i < 200 && (rig.hub().sessionCount() > 0 || rig.server().openConnections() > 0); ++i)
    std::this_thread::sleep_for(10ms);
  EXPECT_EQ(rig.hub().sessionCount(), 0u);
  EXPECT_EQ(rig.server().openConnections(), 0u);
  EXPECT_EQ(rig.server().openWebSockets(), 0u);
  EXPECT_LE(rig.hub().resumeStore().size(), 64u) << "resume states are capped";
  EXPECT_EQ(rig.hub().metrics().sessions.load(), 0);
#if !defined(__SANITIZE_ADDRESS__)  // ASan's quarantine holds freed memory on purpose; LeakSanitizer checks there
  EXPECT_LT(residentKiB() - residentBefore, 8 * 1024) << "resident memory grew over 800 cycles";
#else
  (void)residentBefore;
#endif
}

TEST(StreamingServerTiming, ShutdownClosesEveryClientWithGoingAwayWithinASecond) {
  ServerRig rig;
  auto a = rig.connect(Encoding::Proto), b = rig.connect(Encoding::Json);
  ASSERT_TRUE(a && b);
  greet(*a);
  greet(*b);
  const auto start = std::chrono::steady_clock::now();
  std::thread stopper([&] { rig.server().shutdown(900ms); });
  EXPECT_EQ(closeCodeAfter(*a, 1s), 1001);
  EXPECT_EQ(closeCodeAfter(*b, 1s), 1001);
  stopper.join();
  EXPECT_LT(std::chrono::steady_clock::now() - start, 1s);
}

TEST(StreamingServer, ShutdownReleasesTheSessionOfAClientThatNeverAnswersTheCloseFrame) {
  ServerRig rig;
  auto silent = rig.connect(Encoding::Proto);
  ASSERT_TRUE(silent);
  greet(*silent);
  ASSERT_EQ(rig.hub().sessionCount(), 1u);
  // The client reads nothing more, so the close handshake cannot finish within the grace.
  rig.server().shutdown(20ms);
  EXPECT_EQ(rig.hub().sessionCount(), 0u) << "the connection and its session held each other";
  EXPECT_EQ(rig.server().openWebSockets(), 0u);
}

// A raw TCP connection that sends `bytes` (maybe nothing) and then only listens; returns whether the
// server closed it within `within`.
bool serverHangsUpOn(std::uint16_t port, const std::string& bytes, std::chrono::milliseconds within) {
  boost::asio::io_context io;
  boost::asio::ip::tcp::socket socket(io);
  boost::system::error_code error;
  socket.connect({boost::asio::ip::make_address("127.0.0.1"), port}, error);
  if (error) return false;
  if (!bytes.empty()) boost::asio::write(socket, boost::asio::buffer(bytes), error);
  bool closed = false;
  char sink[4096];
  std::function<void()> readMore = [&] {
    socket.async_read_some(boost::asio::buffer(sink), [&](boost::system::error_code e, std::size_t) {
      if (e) closed = true;
      else readMore();
    });
  };
  readMore();
  io.run_for(within);
  return closed;
}

TEST(StreamingServerTiming, ConnectionsThatNeverFinishTheirRequestAreDroppedAtTheHandshakeDeadline) {
  RigOptions options = defaultRigOptions();
  options.server.handshakeTimeout = 300ms;
  ServerRig rig(options);
  EXPECT_TRUE(serverHangsUpOn(rig.port(), "", 2s)) << "silent connection";
  EXPECT_TRUE(serverHangsUpOn(rig.port(), "GET / HTTP/1.1\r\nHost: x\r\n", 2s)) << "half a request (slowloris)";
  EXPECT_TRUE(serverHangsUpOn(rig.port(), std::string(20000, 'A'), 2s)) << "an endless header line";
  EXPECT_TRUE(serverHangsUpOn(rig.port(), std::string("\x16\x03\x01\x02\x00\x01\x00\x01\xfc\x03\x03", 11), 2s))
      << "a TLS hello on the plain port";
  for (int i = 0; i < 100 && rig.server().openConnections() > 0; ++i) std::this_thread::sleep_for(10ms);
  EXPECT_EQ(rig.server().openConnections(), 0u);
  auto client = rig.connect();
  ASSERT_TRUE(client);
  EXPECT_FALSE(greet(*client).session_id().empty()) << "the server still serves";
}

TEST(StreamingServerTiming, AClientThatNeverSaysHelloIsClosedAndFreesItsSessionSlot) {
  RigOptions options = defaultRigOptions();
  options.hub.maxSessions = 1;
  options.server.firstMessageTimeout = 300ms;
  ServerRig rig(options);
  auto silent = rig.connect();
  ASSERT_TRUE(silent);
  EXPECT_EQ(closeCodeAfter(*silent, 2s), 1008) << "closed at the first-message deadline";
  for (int i = 0; i < 100 && rig.hub().sessionCount() > 0; ++i) std::this_thread::sleep_for(10ms);
  auto next = rig.connect();
  ASSERT_TRUE(next);
  EXPECT_FALSE(greet(*next).session_id().empty()) << "the slot it held is free again";
}

TEST(StreamingServerSecurity, ANonLoopbackBindNeedsAToken) {
  RigOptions options = defaultRigOptions();
  options.server.bindAddress = "0.0.0.0";
  std::atomic<int> renders{0};
  auto factory = [&]() -> Result<std::unique_ptr<session::FrameRenderer>> {
    return std::unique_ptr<session::FrameRenderer>(new FakeRenderer({}, renders));
  };
  auto scene = std::make_shared<const scene::Scene>(*scene::makeBuiltinScene("quad"));
  auto hub = session::SessionHub::start(scene, options.hub, factory);
  ASSERT_TRUE(hub);
  auto refused = net::HttpServer::start(options.server, **hub);
  ASSERT_FALSE(refused);
  EXPECT_NE(refused.error().find("--token"), std::string::npos) << refused.error();
  (*hub)->stop();
}

TEST(StreamingServerSecurity, WithATokenOnlyClientsThatPresentItGetIn) {
  RigOptions options = defaultRigOptions();
  options.server.bindAddress = "0.0.0.0";
  options.server.token = "s3cret-token";
  ServerRig rig(options);
  auto without = client::SpeculaClient::connect({"127.0.0.1", rig.port(), ""}, Encoding::Proto, 2s);
  ASSERT_FALSE(without);
  EXPECT_NE(without.error().find("401"), std::string::npos) << without.error();
  auto wrong = client::SpeculaClient::connect({"127.0.0.1", rig.port(), "s3cret-tokeX"}, Encoding::Proto, 2s);
  EXPECT_FALSE(wrong);
  auto with = rig.connect(Encoding::Proto, "s3cret-token");
  ASSERT_TRUE(with);
  EXPECT_FALSE(greet(*with).session_id().empty());
  EXPECT_EQ(httpRequest(rig.port(), "/metrics").status, 401);
  EXPECT_EQ(httpRequest(rig.port(), "/metrics?token=s3cret-token").status, 200);
  EXPECT_EQ(httpRequest(rig.port(), "/healthz").status, 200) << "health checks need no token";
}

TEST(StreamingServerSecurity, ATokenInTheUrlIsPercentDecodedAsBrowsersEncodeIt) {
  RigOptions options = defaultRigOptions();
  options.server.token = "a b&c%";
  ServerRig rig(options);
  EXPECT_EQ(httpRequest(rig.port(), "/metrics?token=a%20b%26c%25").status, 200);
  EXPECT_EQ(httpRequest(rig.port(), "/metrics?token=a%20b%26c").status, 401);
  EXPECT_EQ(httpRequest(rig.port(), "/metrics?token=a%2").status, 401) << "a broken escape is no match, not a crash";
  auto client = rig.connect(Encoding::Proto, "a b&c%");
  ASSERT_TRUE(client) << "the client encodes the token";
  EXPECT_FALSE(greet(*client).session_id().empty());
  auto parsed = client::parseServerUrl("ws://127.0.0.1:" + std::to_string(rig.port()) + "/ws?token=a%20b%26c%25");
  ASSERT_TRUE(parsed);
  EXPECT_EQ(parsed->token, "a b&c%") << "a URL's token is decoded once";
}

// ---- HTTP routes ----

TEST(StreamingServerHttp, ServesHealthMetricsAndStaticFilesAndNothingOutsideTheWebRoot) {
  RigOptions options = defaultRigOptions();
  options.server.webRoot = SPECULA_TEST_DATA_DIR "/web";
  ServerRig rig(options);
  const HttpReply health = httpRequest(rig.port(), "/healthz");
  EXPECT_EQ(health.status, 200);
  EXPECT_EQ(health.body, "ok\n");
  auto client = rig.connect();
  ASSERT_TRUE(client);
  greet(*client);
  ASSERT_TRUE(receiveUntil(*client, isFrame));
  const HttpReply metrics = httpRequest(rig.port(), "/metrics");
  EXPECT_EQ(metrics.status, 200);
  for (const char* name : {"specula_sessions 1", "specula_frames_sent_total", "specula_frames_skipped_total",
                           "specula_write_timeouts_total 0", "specula_frame_bytes_sent_total",
                           "specula_render_milliseconds_bucket{le=\"+Inf\"}", "specula_encode_milliseconds_count",
                           "specula_input_to_frame_milliseconds_sum"})
    EXPECT_NE(metrics.body.find(name), std::string::npos) << name;
  const HttpReply index = httpRequest(rig.port(), "/");
  EXPECT_EQ(index.status, 200);
  EXPECT_NE(index.body.find("specula test page"), std::string::npos);
  for (const char* outside : {"/../CMakeLists.txt", "/%2e%2e/CMakeLists.txt", "/.hidden", "//etc/passwd", "/a/../../x"})
    EXPECT_EQ(httpRequest(rig.port(), outside).status, 404) << outside;
  EXPECT_EQ(httpRequest(rig.port(), "/healthz", boost::beast::http::verb::post).status, 405);
  EXPECT_EQ(httpRequest(rig.port(), "/ws").status, 426);
}

}  // namespace
}  // namespace specula::testing

namespace specula::testing {
namespace {

TEST(LoadRunTiming, MeasuresEverySessionAgainstARealServer) {
  RigOptions options = defaultRigOptions();
  options.renderer.delay = 5ms;
  ServerRig rig(options);
  client::LoadOptions load;
  load.address = {"127.0.0.1", rig.port(), ""};
  load.sessions = 3;
  load.width = 64;
  load.height = 32;
  load.warmup = 200ms;
  load.duration = 1000ms;
  int progressCalls = 0;
  load.progress = [&](double, std::uint64_t) { ++progressCalls; };
  const client::LoadReport report = client::runLoad(load);
  ASSERT_EQ(report.sessions.size(), 3u);
  EXPECT_EQ(report.errors, 0u);
  for (const client::SessionLoad& session : report.sessions) {
    EXPECT_GT(session.frames, 5u) << session.error;
    EXPECT_FALSE(session.latencyMs.empty());
  }
  EXPECT_GT(report.fpsMin, 5.0);
  EXPECT_GT(report.latencyP50, 0.0);
  EXPECT_GE(report.latencyP99, report.latencyP50);
  EXPECT_GE(report.latencyMax, report.latencyP99);
  EXPECT_NEAR(report.renderMsMean, 5.0, 3.0) << "server timings are carried through";
  EXPECT_GT(report.bytesPerFrame, 100.0);
  EXPECT_GE(progressCalls, 1);
  const std::string json = client::loadReportJson(report);
  for (const char* key : {"\"fps_per_session_mean\"", "\"latency_ms_p99\"", "\"bytes_per_frame\"", "\"sessions\""})
    EXPECT_NE(json.find(key), std::string::npos) << key;
}

TEST(LoadRun, ReportsAnUnreachableServerAsSessionErrors) {
  client::LoadOptions load;
  load.address = {"127.0.0.1", 1, ""};  // nothing listens on port 1
  load.sessions = 2;
  load.warmup = 0ms;
  load.duration = 200ms;
  const client::LoadReport report = client::runLoad(load);
  EXPECT_EQ(report.errors, 2u);
  EXPECT_NE(report.sessions[0].error.find("cannot connect to 127.0.0.1:1"), std::string::npos)
      << report.sessions[0].error;
}

}  // namespace
}  // namespace specula::testing
