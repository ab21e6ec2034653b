#include "gl/ShaderSource.h"

#include <cctype>
#include <optional>

namespace specula::gl {

namespace {

constexpr int kMaxIncludeDepth = 8;
constexpr std::string_view kInclude = "#include \"";

// Splits off the first line of `text`, its newline included.
std::string_view takeLine(std::string_view& text) {
  const std::size_t end = text.find('\n');
  const std::string_view line = text.substr(0, end == std::string_view::npos ? text.size() : end + 1);
  text.remove_prefix(line.size());
  return line;
}

struct Expansion {
  const ShaderFiles& files;
  std::set<std::string_view> included;
  ExpandedShader shader;
};

// Appends `file` to the expansion as source string S = its index in shader.files. An included file
// restarts the numbering at its line 1; after it, its includer's numbering resumes.
Status expandInto(Expansion& expansion, std::string_view file, int depth) {
  const auto found = expansion.files.find(file);
  if (found == expansion.files.end())
    return Error{"shader file shaders/" + std::string(file) + " is not embedded (rebuild?)"};
  if (depth > kMaxIncludeDepth) return Error{"shaders/" + std::string(file) + ": #include nested too deeply"};
  const std::string number = std::to_string(expansion.shader.files.size());
  expansion.shader.files.emplace_back(file);
  std::string& out = expansion.shader.text;
  if (depth > 0) out += "#line 1 " + number + "\n";
  std::string_view text = found->second;
  bool versioned = depth > 0;  // #line before #version would fail to compile
  for (int lineNumber = 1; !text.empty(); ++lineNumber) {
    const std::string_view line = takeLine(text);
    versioned = versioned || line.starts_with("#version");
    if (!line.starts_with(kInclude)) {
      out += line;
      continue;
    }
    if (!versioned) return Error{"shaders/" + std::string(file) + ": #include before #version"};
    const std::size_t close = line.find('"', kInclude.size());
    if (close == std::string_view::npos) return Error{"shaders/" + std::string(file) + ": malformed #include"};
    const std::string_view included = line.substr(kInclude.size(), close - kInclude.size());
    if (!expansion.included.insert(included).second) {
      out += '\n';  // already included: an empty line keeps the numbering
      continue;
    }
    if (Status status = expandInto(expansion, included, depth + 1); !status) return status;
    if (!out.ends_with('\n')) out += '\n';
    out += "#line " + std::to_string(lineNumber + 1) + " " + number + "\n";
  }
  return {};
}

// Reads the decimal number at text[at], moving `at` past it.
std::optional<std::size_t> readNumber(std::string_view text, std::size_t& at) {
  const std::size_t start = at;
  std::size_t value = 0;
  for (; at < text.size() && at - start < 9 && std::isdigit(static_cast<unsigned char>(text[at])); ++at)
    value = value * 10 + static_cast<std::size_t>(text[at] - '0');
  if (at == start) return std::nullopt;
  return value;
}

struct LogPosition {
  std::size_t source = 0, line = 0;
  std::optional<std::size_t> column;
  std::size_t message = 0;  // where the text after the position starts
};

// The position a log line starts with: "S:LINE(COL): " (Mesa) or "S(LINE) : " (NVIDIA).
std::optional<LogPosition> positionOf(std::string_view line) {
  LogPosition position;
  std::size_t at = 0;
  const auto source = readNumber(line, at);
  if (!source || at >= line.size()) return std::nullopt;
  position.source = *source;
  const bool mesa = line[at] == ':';
  if (!mesa && line[at] != '(') return std::nullopt;
  const auto number = readNumber(line, ++at);
  if (!number) return std::nullopt;
  position.line = *number;
  if (mesa && line.substr(at).starts_with("(")) {
    position.column = readNumber(line, ++at);
    if (!position.column || !line.substr(at).starts_with(")")) return std::nullopt;
    ++at;
  }
  const std::string_view end = mesa ? ": " : ") : ";
  if (!line.substr(at).starts_with(end)) return std::nullopt;
  position.message = at + end.size();
  return position;
}

bool isIdentifierCharacter(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

std::string_view trimmed(std::string_view text) {
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front()))) text.remove_prefix(1);
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.remove_suffix(1);
  return text;
}

// The name one declarator of a uniform declaration introduces: its last identifier before any array
// size or initializer ("uniform vec4 light[4]" → light).
std::string_view declaredName(std::string_view declarator) {
  declarator = trimmed(declarator.substr(0, declarator.find_first_of("[=")));
  std::size_t start = declarator.size();
  while (start > 0 && isIdentifierCharacter(declarator[start - 1])) --start;
  return declarator.substr(start);
}

}  // namespace

Result<ExpandedShader> expandShader(std::string_view file, const ShaderFiles& files) {
  Expansion expansion{files, {file}, {}};
  if (Status status = expandInto(expansion, file, 0); !status) return Error{status.error()};
  return std::move(expansion.shader);
}

std::string attributeShaderLog(std::string_view log, const std::vector<std::string>& files) {
  std::string out;
  while (!log.empty()) {
    const std::string_view line = takeLine(log);
    const auto position = positionOf(line);
    if (!position || position->source >= files.size()) {
      out += line;
      continue;
    }
    out += "shaders/" + files[position->source] + ":" + std::to_string(position->line) + ":";
    if (position->column) out += std::to_string(*position->column) + ":";
    out += " ";
    out += line.substr(position->message);
  }
  return out;
}

std::set<std::string, std::less<>> declaredUniforms(std::string_view source) {
  std::set<std::string, std::less<>> names;
  while (!source.empty()) {
    std::string_view line = takeLine(source);
    line = line.substr(0, line.find("//"));
    while (!line.empty()) {  // each statement on the line
      const std::size_t semicolon = line.find(';');
      if (semicolon == std::string_view::npos) break;  // not a declaration, or a block's opening line
      std::string_view statement = trimmed(line.substr(0, semicolon));
      line.remove_prefix(semicolon + 1);
      if (statement.starts_with("layout")) statement = trimmed(statement.substr(statement.find(')') + 1));
      if (!statement.starts_with("uniform ")) continue;
      for (std::size_t comma = 0; comma != std::string_view::npos;) {
        comma = statement.find(',');
        const std::string_view name = declaredName(statement.substr(0, comma));
        if (!name.empty()) names.emplace(name);
        statement.remove_prefix(comma == std::string_view::npos ? statement.size() : comma + 1);
      }
    }
  }
  return names;
}

}  // namespace specula::gl
