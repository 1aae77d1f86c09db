#pragma once
// The one exception type for bad input. `where` names the place (file:line, a JSON pointer,
// or a CLI flag) and the message says what was expected; the CLI prints "where: message".
#include <stdexcept>
#include <string>

namespace rayo {

class InputError : public std::runtime_error {
  public:
    InputError(std::string where, const std::string& message)
        : std::runtime_error(where.empty() ? message : where + ": " + message),
          m_where(std::move(where)),
          m_message(message) {}
    const std::string& where() const { return m_where; }
    const std::string& message() const { return m_message; }

  private:
    std::string m_where;
    std::string m_message;
};

}  // namespace rayo
