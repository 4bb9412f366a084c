// Orthotropic growth Fg = diag(g1, g2, g3).
#include <cosmo/materials/growth.h>

namespace cosmo
{
  namespace materials
  {
    class OrthotropicGrowth : public BulkGrowthLaw
    {
    public:
      static void
      declare_parameters(ParameterHandler &)
      {}
      void
      parse_parameters(ParameterHandler &prm, const std::string &where) override
      {
        factors.parse(prm, where, 3);
      }
      Tensor<2, 3>
      value(const Point<2> &X, const double t) const override
      {
        Tensor<2, 3> Fg;
        for (unsigned int i = 0; i < 3; ++i)
          Fg[i][i] = factors.ramped(X, t, i);
        return Fg;
      }
      std::string
      description() const override
      {
        return "orthotropic, (g1; g2; g3) = (" + factors.text() + ")";
      }

    private:
      GrowthFactors factors;
    };

    COSMO_REGISTER_PLUGIN(BulkGrowthLaw,
                          OrthotropicGrowth,
                          "orthotropic",
                          "diag(g1, g2, g3) from 'Growth factor' given as three expressions "
                          "separated by ';'.")
  } // namespace materials
} // namespace cosmo
