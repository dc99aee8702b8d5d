// gradcontact/analytic: the JSON Lines evaluator behind `gradcontact eval` (vocabulary, units and
// sign conventions in analytic/README.md).
//
// One request object a line in, one answer line out: {"id": ..., "value": x} or
// {"id": ..., "error": "..."}; the error names the parameter, its value and the valid range. One bad
// line never stops the others.
#ifndef GRADCONTACT_ANALYTIC_BATCH_H
#define GRADCONTACT_ANALYTIC_BATCH_H

#include <iosfwd>
#include <memory>
#include <string>

namespace gradcontact::batch
{
  /// The answer to one request.
  struct Answer
  {
    std::string id_json; ///< the request's id, re-serialised ("null" when absent or unreadable)
    bool ok;             ///< true: value holds the result; false: error holds the message
    double value;
    std::string error;
  };

  /// Evaluates one request line. Never throws: every failure becomes Answer::error.
  Answer evaluate(const std::string &line);

  /// One JSON line, without the newline.
  std::string to_json(const Answer &answer);

  /// A parsed and checked request, ready to be evaluated repeatedly without parsing (benchmarks).
  class Prepared
  {
  public:
    /// The value; throws DomainError (or another std::exception) exactly where evaluate() reports an error.
    double operator()() const;
    struct Impl;

  private:
    friend Prepared prepare(const std::string &line);
    std::shared_ptr<const Impl> impl_;
  };

  /// Parses a request line; throws DomainError for what evaluate() would report before evaluating
  /// (invalid JSON, unknown keys, case, quantity or method).
  Prepared prepare(const std::string &line);

  /// Reads requests from `in` until EOF and writes one answer line per non-blank request line.
  /// Returns the number of answers that are errors.
  int evaluate_stream(std::istream &in, std::ostream &out);
} // namespace gradcontact::batch

#endif
