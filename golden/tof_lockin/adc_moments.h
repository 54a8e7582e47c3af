#pragma once
// Mean and variance of one column-ADC conversion of a noisy tap voltage (thesis eq. 4.9).
//
// The ADC of eq. 4.9 truncates: code = floor(V / Delta), clipped to 0 .. 2^bits - 1, and the
// value used is code x Delta. For V ~ Normal(mu, sigma^2) (Poisson shot noise of thousands of
// electrons plus Gaussian kTC / read noise; the Gaussian form is the one approximation here):
//   E[code]   = sum_{k=1}^{K-1} P(V >= k Delta)            (K = 2^bits)
//   E[code^2] = sum_{k=1}^{K-1} (2k - 1) P(V >= k Delta)
// summed over the codes within mu +- 9 sigma (outside, P is 0 or 1 to 1e-19). When sigma >= 1.5
// Delta and no clipping code is within 9 sigma, the error of a truncating quantiser is uniform
// and independent of V to within exp(-2 pi^2 sigma^2 / Delta^2) < 1e-19 (Sheppard), so
//   E[value] = mu - Delta / 2,  Var[value] = sigma^2 + Delta^2 / 12
// in closed form. With sigma -> 0 the value is deterministic: floor(mu / Delta) Delta, the
// deterministic quantisation error that shows up as range bias.
namespace rangesim::golden {

struct QuantisedMoments {
  double mean_V = 0;  // E[code x Delta]
  double var_V2 = 0;  // Var[code x Delta]
};

QuantisedMoments quantised_moments(double mean_V, double sigma_V, double lsb_V, long long codes);

}  // namespace rangesim::golden
