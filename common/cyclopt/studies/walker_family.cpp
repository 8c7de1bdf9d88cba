#include "cyclopt/studies/walker_family.hpp"

#include "cyclopt/walker/model_parameters.hpp"

#include <algorithm>
#include <stdexcept>

namespace cyclopt::studies {

ParametricProblem walker_family(const walker::WalkerModel<double>& model, const walker::GaitProblemOptions& options,
                                const std::string& parameter) {
  if (parameter == "speed")
    return {parameter, [model, options](double v) {
              walker::GaitProblemOptions o = options;
              o.speed = v;
              return std::make_unique<walker::GaitProblem>(model, o);
            }};
  const int index = walker::model_parameter_index(model, parameter);  // throws with the valid names
  if (std::find(options.free_parameters.begin(), options.free_parameters.end(), parameter) != options.free_parameters.end())
    throw std::invalid_argument("parameter: \"" + parameter + "\" is optimised (free_parameters) and cannot be continued");
  if (walker::follows_foot_geometry(model, index))
    throw std::invalid_argument("parameter: \"" + parameter +
                                "\" follows the foot geometry with a density (appendix E) and cannot be continued alone");
  const Eigen::VectorXd base = walker::model_parameters(model);
  return {parameter, [model, options, index, base](double value) {
            Eigen::VectorXd p = base;
            p[index] = value;
            return std::make_unique<walker::GaitProblem>(walker::with_model_parameters<double>(model, p), options);
          }};
}

}  // namespace cyclopt::studies
