// gradcontact/analytic: the evaluator of requests (request.h): one dispatch table a case, closed form
// or numerical MDR, and the JSON Lines loop behind `gradcontact eval` (vocabulary, units and sign
// conventions in analytic/README.md).
//
// A scene, a figure or a benchmark builds a Request and calls evaluate(); `gradcontact eval` reads one
// JSON object a line and answers {"id": ..., "value": x} or {"id": ..., "error": "..."}; the error names
// the parameter, its value and the valid range. One bad line never stops the others.
#ifndef GRADCONTACT_ANALYTIC_BATCH_H
#define GRADCONTACT_ANALYTIC_BATCH_H

#include <analytic/request.h>

#include <iosfwd>
#include <memory>
#include <string>

namespace gradcontact::batch
{
  /// The value; DomainError for an unknown case or quantity, a missing or invalid input, and a result
  /// that is not finite (named with the request's inputs).
  double evaluate(const Request &request);

  /// A request checked for its case and quantity and ready to be evaluated repeatedly (benchmarks:
  /// the equivalent medium is computed once).
  class Prepared
  {
  public:
    /// The value; throws exactly where evaluate() would.
    double operator()() const;
    struct Impl;

  private:
    friend Prepared prepare(const Request &request);
    std::shared_ptr<const Impl> impl_;
  };

  /// DomainError for an unknown case, quantity or method pair.
  Prepared prepare(const Request &request);

  /// The answer to one request line.
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

  /// Reads requests from `in` until EOF and writes one answer line per non-blank request line.
  /// Returns the number of answers that are errors.
  int evaluate_stream(std::istream &in, std::ostream &out);
} // namespace gradcontact::batch

#endif
