#ifndef tribodyn_contact_spectrum_h
#define tribodyn_contact_spectrum_h

#include <complex>
#include <vector>

namespace tribodyn
{
  namespace contact
  {
    /// In-place forward discrete Fourier transform (FFTW), any size:
    /// X_k = sum_j x_j exp(-2 pi i j k / n).
    void
    fft(std::vector<std::complex<double>> &data);

    /**
     * One-sided amplitude spectrum of the uniformly sampled signal
     * @p samples (spacing @p sample_spacing seconds): the mean is removed,
     * a Hann window applied, the signal zero-padded to a power of two (at
     * least 4 times the length, for a finer frequency grid), and the
     * amplitudes scaled so that a sine of amplitude A shows a peak of about
     * A. Returns pairs (frequency in Hz, amplitude).
     */
    std::vector<std::pair<double, double>>
    amplitude_spectrum(const std::vector<double> &samples,
                       const double               sample_spacing);

    /// Frequency (Hz) of the largest amplitude above zero frequency (0 if
    /// the spectrum has fewer than two points).
    double
    dominant_frequency(const std::vector<std::pair<double, double>> &spectrum);
  } // namespace contact
} // namespace tribodyn

#endif
