#include "linkproof/core/error.h"

#include <fmt/format.h>

namespace linkproof {

InputError::InputError(std::string source, std::string field, std::string problem)
    : Error(fmt::format("{}: {}: {}", source, field.empty() ? "(document)" : field, problem)),
      source_(std::move(source)),
      field_(std::move(field)),
      problem_(std::move(problem)) {}

UndefinedQuantity::UndefinedQuantity(std::string quantity, std::string reason)
    : Error(fmt::format("{} is undefined: {}", quantity, reason)),
      quantity_(std::move(quantity)),
      reason_(std::move(reason)) {}

void assertion_failed(const char* expr, const char* file, int line, const std::string& msg) {
  throw InternalError(fmt::format("internal error at {}:{}: assertion `{}` failed: {}", file, line,
                                  expr, msg));
}

}  // namespace linkproof
