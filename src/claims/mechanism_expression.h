// A mechanism claim expression: text in the mechanism language of vocabulary.h, parsed into a
// tree whose every node has a kind (number or vector), checked before any scene is seen.
//
// Grammar (the usual precedence; `^` binds tighter than a sign, as in -x^2 = -(x^2)):
//   expression := term (('+' | '-') term)*
//   term       := factor (('*' | '/') factor)*
//   factor     := ('+' | '-') factor | atom ('^' exponent)?
//   atom       := integer | '(' expression ')' | word '(' argument (',' argument)* ')'
//   argument   := name | '"' name '"' | expression      (as the word's table entry asks)
//   exponent   := integer | '(' ['-'] integer ')'       (|exponent| <= 64)
// Numbers are integers; a fraction is a division (1/2). Kind rules: + and - join two numbers
// or two vectors; * at most one vector; / and ^ numbers only (a vector may be divided by a
// number). Every error is an InputError whose source is "FILE:LINE:COLUMN" of the offending
// character and whose field names the claim (ExpressionContext::field).
//
// Names are resolved against a scene by bind_names (mechanism/mechanism_data_claim.h); the
// tree keeps where each name was written so that an unknown name is refused at its column.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "claims/claim_expression.h"
#include "claims/vocabulary.h"
#include "linkproof/core/exact.h"

namespace linkproof {

struct MechanismNode {
  enum class Op { Constant, Add, Subtract, Multiply, Divide, Negate, Power, Call, Name };
  Op op = Op::Constant;
  ClaimKind kind = ClaimKind::Number;          ///< Number or Vector (a Name: its argument kind)
  Rational constant;                           ///< Constant
  int exponent = 1;                            ///< Power
  const Word* word = nullptr;                  ///< Call
  std::string name;                            ///< Name: as written, without quotes
  int index = -1;                              ///< Name: link, joint or point index once bound
  bool is_tracer_point = false;                ///< Name of kind Point: a tracer point, not a joint
  std::string text;                            ///< the node's text as written (for messages)
  std::string where;                           ///< "FILE:LINE:COLUMN" of its first character
  std::vector<MechanismNode> children;
};

class MechanismExpression {
 public:
  /// Parses and kind-checks `text`; throws InputError naming file:line:column and the field.
  static MechanismExpression parse(const std::string& text, const ExpressionContext& context,
                                   const PositionMap& positions);
  static MechanismExpression parse(const std::string& text, const ExpressionContext& context = {}) {
    return parse(text, context, standalone_positions(text));
  }

  const std::string& text() const { return text_; }
  const std::string& field() const { return field_; }
  ClaimKind kind() const { return root_.kind; }
  const MechanismNode& root() const { return root_; }
  MechanismNode& root() { return root_; }

 private:
  std::string text_, field_;
  MechanismNode root_;
};

}  // namespace linkproof
