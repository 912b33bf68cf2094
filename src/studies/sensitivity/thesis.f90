!> The thesis's sensitivity study (§III.3.2): the improved MODJOIN set of table III.2 at
!> sigma_n0 = 56 kPa on CNL and CND paths, the perturbations of tables III.3 and III.4 (they
!> differ for beta only: +/-50 % in III.3, +/-15 % in III.4, doc/theory.md §6.4) and table III.4's
!> normalised Q_p (%), copied as printed, as the reference column of the reports.
module pecplas_studies_sensitivity_thesis
   use pecplas_base_kinds, only: wp
   use pecplas_base_params, only: params_t
   use pecplas_studies_path_deck, only: PATH_CNL, PATH_CND
   use pecplas_studies_sensitivity_core, only: curve_spec_t, OUT_TAU, OUT_EPS_N, OUT_SIGMA_N
   implicit none (type, external)
   private

   public :: THESIS_KEYS, THESIS_LABELS, FRACTIONS_III3, FRACTIONS_III4, TABLE_III4
   public :: CURVE_LABELS, thesis_curves, table_iii2_params, THESIS_SIGMA_N0, THESIS_EPS_T

   !> Parameters in the order of tables III.3 and III.4 (deck keys of TYPE=MODJOIN).
   character(len=*), parameter :: THESIS_KEYS(10) = [character(len=5) :: 'K0', 'G0', 'PHI', &
      'R0', 'BETA', 'ALPHA', 'A', 'B', 'PSI', 'A_G']
   character(len=*), parameter :: THESIS_LABELS(10) = [character(len=5) :: 'K0', 'G0', 'phi', &
      'R0', 'beta', 'alpha', 'A', 'B', 'psi', 'a_g']
   !> Perturbations (fractions) of table III.3 and of table III.4.
   real(wp), parameter :: FRACTIONS_III3(10) = [0.30_wp, 0.30_wp, 0.10_wp, 0.30_wp, 0.50_wp, &
      0.15_wp, 0.30_wp, 0.30_wp, 0.20_wp, 0.30_wp]
   real(wp), parameter :: FRACTIONS_III4(10) = [0.30_wp, 0.30_wp, 0.10_wp, 0.30_wp, 0.15_wp, &
      0.15_wp, 0.30_wp, 0.30_wp, 0.20_wp, 0.30_wp]
   !> Table III.4 (%): columns CNL eps_t-tau, CNL eps_t-eps_n, CND eps_t-tau, CND eps_t-sigma_n.
   real(wp), parameter :: TABLE_III4(10, 4) = reshape([ &
      0.0_wp, 0.17_wp, 33.0_wp, 20.0_wp, 0.37_wp, 8.0_wp, 8.0_wp, 100.0_wp, 0.0_wp, 0.0_wp, &
      0.0_wp, 0.07_wp, 63.0_wp, 36.6_wp, 1.9_wp, 11.8_wp, 18.0_wp, 100.0_wp, 58.0_wp, 20.0_wp, &
      10.0_wp, 0.09_wp, 33.0_wp, 18.5_wp, 0.88_wp, 6.0_wp, 8.0_wp, 100.0_wp, 20.0_wp, 7.0_wp, &
      30.0_wp, 0.32_wp, 61.0_wp, 34.6_wp, 2.0_wp, 15.5_wp, 18.8_wp, 100.0_wp, 59.0_wp, 21.6_wp], &
      [10, 4])
   character(len=*), parameter :: CURVE_LABELS(4) = [character(len=15) :: 'CNL eps_t-tau', &
      'CNL eps_t-eps_n', 'CND eps_t-tau', 'CND eps_t-sig_n']
   !> The thesis's path: sigma_n0 = 56 kPa, eps_t from 0 to 6 mm (figures III.17-III.22).
   real(wp), parameter :: THESIS_SIGMA_N0 = 56.0_wp, THESIS_EPS_T = 6.0_wp

contains

   !> The four curves of table III.4.
   pure function thesis_curves() result(curves)
      type(curve_spec_t) :: curves(4)
      curves = [curve_spec_t(PATH_CNL, OUT_TAU), curve_spec_t(PATH_CNL, OUT_EPS_N), &
         curve_spec_t(PATH_CND, OUT_TAU), curve_spec_t(PATH_CND, OUT_SIGMA_N)]
   end function thesis_curves

   !> Table III.2 (improved version, dense Hostun sand on steel) as *INTERFACE_LAW,
   !> TYPE=MODJOIN, LENGTH_UNIT=MM parameters (kPa, mm; LENGTH_UNIT as metres, as the deck
   !> readers pass it).
   function table_iii2_params() result(p)
      type(params_t) :: p
      p%file = '<table III.2>'
      p%line = 0
      p%keyword = '*INTERFACE_LAW'
      allocate (p%keys(0), p%values(0))
      call p%add('K0', 80.0_wp)
      call p%add('G0', 40.0_wp)
      call p%add('PHI', 41.0_wp)
      call p%add('C', 0.0_wp)
      call p%add('R0', 0.3_wp)
      call p%add('BETA', 1.5_wp)
      call p%add('ALPHA', 0.7_wp)
      call p%add('A', 0.6_wp)
      call p%add('B', 0.96_wp)
      call p%add('PSI', 27.0_wp)
      call p%add('A_G', 0.4_wp)
      call p%add('LENGTH_UNIT', 1.0e-3_wp)
   end function table_iii2_params

end module pecplas_studies_sensitivity_thesis
