!> Friction between the outer and inner tubes of the primary strut (paper eqs. 23-26, section 2.7).
!!
!! The secondaries load the primary's outer tube at its lugs e, f. The component of their
!! combined force perpendicular to the primary axis (eq. 23),
!!     N_E/F = | F_L + F_R - ((F_L + F_R) . u_p) u_p |,   F_L = N_L u_L,  F_R = N_R u_R,
!! (N axial force, compression positive; u the strut axis from its upper joint toward the lug,
!! along which a compressed strut pushes the lug) is carried across the telescopic joint by two
!! bearing reactions N_A (at the outer tube's lower end) and N_B (at the inner tube's upper end).
!! A load at the lever arm L_O1 outside a bearing span of length L_I + L_O - L_L gives
!!     eta1 = (|N_A| + |N_B|)/N_E/F = 1 + 2 L_O1/(L_I + L_O - L_L)                      (eq. 26)
!! and the cosine pressure distribution over the half circumference gives
!!     eta2 = int p dl / N_E/F = 4/pi                                                  (eq. 26)
!! so the sliding friction between the tubes is eta u_1 N_E/F, eta = eta1 eta2 (eq. 25), and the
!! primary's crush force becomes F_pri + eta u_1 N_E/F (eq. 24).
!!
!! Use (landyn_tripod_gear): the extra bound is computed explicitly, once per step, from the secondary
!! axial forces of the previous step and the current strut axes, and added to the primary's
!! bounds against motion in each direction (the friction opposes the sliding, whichever way; it
!! also acts when the strut slides freely inside its crushed range). Rigid stops are unchanged.
!! eta is a constant: the lengths are the tube geometry at the primary length L_L (by default its
!! nominal length), as the paper's single coefficient eta.
module landyn_tube_friction
  use landyn_kinds, only: wp, pi
  use landyn_buffer, only: rigid_force
  use landyn_status, only: STAT_FAILED, status_t
  implicit none
  private

  public :: tube_friction_t, make_tube_friction, tube_eta1, tube_eta2, lateral_lug_force, &
            tube_friction_bound, add_tube_bound

  !> Tube friction of one primary strut.
  type :: tube_friction_t
    logical :: on = .false.     !! tube friction is applied [-]
    real(wp) :: mu = 0.1_wp     !! u_1, friction coefficient between the tubes [-]
    real(wp) :: eta1 = 1.0_wp   !! lever factor [-]
    real(wp) :: eta2 = 1.0_wp   !! pressure distribution factor 4/pi [-]
    real(wp) :: eta = 1.0_wp    !! eta1 eta2 [-]
  end type tube_friction_t

contains

  !> Tube friction from the input lengths. STAT_FAILED when the tubes do not overlap or a value is invalid.
  pure subroutine make_tube_friction(on, mu, l_outer, l_inner, l_leg, l_lever, tf, status)
    logical, intent(in) :: on                   !! apply tube friction [-]
    real(wp), intent(in) :: mu                  !! u_1 [-]
    real(wp), intent(in) :: l_outer             !! L_O, outer tube length [m]
    real(wp), intent(in) :: l_inner             !! L_I, inner tube length [m]
    real(wp), intent(in) :: l_leg               !! L_L, primary length (upper joint to footpad joint) [m]
    real(wp), intent(in) :: l_lever             !! L_O1, lever arm of the lateral load [m]
    type(tube_friction_t), intent(out) :: tf    !! tube friction
    type(status_t), intent(out) :: status       !! STAT_OK, or STAT_FAILED with the reason [-]
    tf%on = on
    if (.not. on) return
    if (.not. (mu >= 0.0_wp .and. mu <= huge(1.0_wp))) then
      call status%fail(STAT_FAILED, '&primary_strut mu_tube must be a finite number >= 0')
    else if (.not. (l_outer > 0.0_wp .and. l_inner > 0.0_wp .and. l_leg > 0.0_wp .and. l_lever >= 0.0_wp)) then
      call status%fail(STAT_FAILED, '&primary_strut tube lengths must be > 0 (tube_lever >= 0)')
    else if (.not. (l_inner + l_outer - l_leg > 0.0_wp)) then
      call status%fail(STAT_FAILED, &
                       '&primary_strut the tubes do not overlap: tube_outer_length + tube_inner_length <= tube_leg_length')
    else
      tf%mu = mu
      tf%eta1 = tube_eta1(l_outer, l_inner, l_leg, l_lever)
      tf%eta2 = tube_eta2()
      tf%eta = tf%eta1*tf%eta2
    end if
  end subroutine make_tube_friction

  !> eta1 = 1 + 2 L_O1 / (L_I + L_O - L_L) (eq. 26); the tubes must overlap.
  pure function tube_eta1(l_outer, l_inner, l_leg, l_lever) result(eta1)
    real(wp), intent(in) :: l_outer   !! L_O [m]
    real(wp), intent(in) :: l_inner   !! L_I [m]
    real(wp), intent(in) :: l_leg     !! L_L [m]
    real(wp), intent(in) :: l_lever   !! L_O1 [m]
    real(wp) :: eta1                  !! lever factor [-]
    eta1 = 1.0_wp + 2.0_wp*l_lever/(l_inner + l_outer - l_leg)
  end function tube_eta1

  !> eta2 = 4/pi (eq. 26: cosine pressure over the contact angle pi/2 each side).
  pure function tube_eta2() result(eta2)
    real(wp) :: eta2                  !! pressure distribution factor [-]
    eta2 = 4.0_wp/pi
  end function tube_eta2

  !> N_E/F (eq. 23): magnitude of the part of the secondaries' combined force on the lugs that is
  !! perpendicular to the primary axis.
  pure function lateral_lug_force(u_p, u_l, u_r, n_l, n_r) result(n_ef)
    real(wp), intent(in) :: u_p(3)    !! primary axis, unit [-]
    real(wp), intent(in) :: u_l(3)    !! left secondary axis (upper joint toward lug), unit [-]
    real(wp), intent(in) :: u_r(3)    !! right secondary axis, unit [-]
    real(wp), intent(in) :: n_l       !! left secondary axial force, compression positive [N]
    real(wp), intent(in) :: n_r       !! right secondary axial force, compression positive [N]
    real(wp) :: n_ef                  !! lateral force [N]
    real(wp) :: f(3)
    f = n_l*u_l + n_r*u_r
    n_ef = norm2(f - dot_product(f, u_p)*u_p)
  end function lateral_lug_force

  !> Extra friction bound eta u_1 N_E/F on the primary (0 when tube friction is off).
  pure function tube_friction_bound(tf, u_p, u_l, u_r, n_l, n_r) result(bound)
    type(tube_friction_t), intent(in) :: tf  !! tube friction
    real(wp), intent(in) :: u_p(3)           !! primary axis, unit [-]
    real(wp), intent(in) :: u_l(3)           !! left secondary axis, unit [-]
    real(wp), intent(in) :: u_r(3)           !! right secondary axis, unit [-]
    real(wp), intent(in) :: n_l              !! left secondary axial force, compression positive [N]
    real(wp), intent(in) :: n_r              !! right secondary axial force, compression positive [N]
    real(wp) :: bound                        !! extra bound [N]
    if (tf%on) then
      bound = tf%eta*tf%mu*lateral_lug_force(u_p, u_l, u_r, n_l, n_r)
    else
      bound = 0.0_wp
    end if
  end function tube_friction_bound

  !> Add the tube-friction bound to the primary's bounds against motion in each direction
  !! (rigid stops, bound >= rigid_force, stay as they are).
  pure subroutine add_tube_bound(extra, f_pos, f_neg)
    real(wp), intent(in) :: extra        !! eta u_1 N_E/F [N]
    real(wp), intent(inout) :: f_pos     !! bound against motion toward +s (shortening) [N]
    real(wp), intent(inout) :: f_neg     !! bound against motion toward -s (extension) [N]
    if (f_pos < rigid_force) f_pos = f_pos + extra
    if (f_neg < rigid_force) f_neg = f_neg + extra
  end subroutine add_tube_bound

end module landyn_tube_friction
