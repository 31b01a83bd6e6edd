!> One strut of a landing gear: its mass properties and the mass functions of its length.
!!
!! A strut is an upper part (mass m_o, centre at l_o from the upper joint, transverse inertia I_o)
!! pivoting with the strut, and a lower part (m_i, centre at l_i from the lower joint, I_i) that
!! also slides with the length L; a point mass m_end (the footpad) may sit at the lower joint.
!! Spin inertia about the strut axis is neglected. About the upper joint, along the axis:
!!   first moment          S(L)  = m_o l_o + m_i (L - l_i) + m_end L,
!!   sliding first moment  S1(L) = m_i (L - l_i) + m_end L,
!!   transverse inertia    J(L)  = m_o l_o^2 + I_o + I_i + m_i (L - l_i)^2 + m_end L^2,
!!   and dJ/dL             = 2 m_i (L - l_i) + 2 m_end L.
!! Every formula of the gear that needs them calls these type-bound functions.
module landyn_strut
  use landyn_kinds, only: wp
  implicit none
  private

  public :: strut_mass_t, strut_t, strut_mass_functions_t, strut_from_mass

  !> Mass properties of one strut (input record).
  type :: strut_mass_t
    real(wp) :: m_o = 0.0_wp    !! upper part mass [kg]
    real(wp) :: l_o = 0.0_wp    !! upper part centre from the upper joint [m]
    real(wp) :: i_o = 0.0_wp    !! upper part transverse inertia about its centre [kg m^2]
    real(wp) :: m_i = 0.0_wp    !! lower (sliding) part mass [kg]
    real(wp) :: l_i = 0.0_wp    !! lower part centre from the lower joint [m]
    real(wp) :: i_i = 0.0_wp    !! lower part transverse inertia about its centre [kg m^2]
    real(wp) :: m_end = 0.0_wp  !! point mass at the lower joint (footpad) [kg]
  end type strut_mass_t

  !> A strut's mass functions at one length, all at once (strut_t%at: one call per strut in the
  !! gear's inner loops).
  type :: strut_mass_functions_t
    real(wp) :: m_s = 0.0_wp      !! sliding mass m_i + m_end [kg]
    real(wp) :: m_tot = 0.0_wp    !! strut mass [kg]
    real(wp) :: s = 0.0_wp        !! first moment S(L) [kg m]
    real(wp) :: s0 = 0.0_wp       !! upper part's first moment m_o l_o [kg m]
    real(wp) :: s1 = 0.0_wp       !! sliding parts' first moment S1(L) [kg m]
    real(wp) :: j = 0.0_wp        !! transverse inertia J(L) [kg m^2]
    real(wp) :: dj = 0.0_wp       !! dJ/dL [kg m]
  end type strut_mass_functions_t

  !> A strut's mass model: the constants of its mass functions (set by strut_from_mass).
  type :: strut_t
    private
    type(strut_mass_t) :: mass                 !! the mass properties it was made from
    real(wp) :: m_s = 0.0_wp                   !! sliding mass m_i + m_end [kg]
    real(wp) :: m_tot = 0.0_wp                 !! strut mass [kg]
    real(wp) :: j_0 = 0.0_wp                   !! m_o l_o^2 + I_o + I_i [kg m^2]
    real(wp) :: s_0 = 0.0_wp                   !! m_o l_o [kg m]
  contains
    procedure :: properties => strut_properties              !! the mass properties the strut was made from
    procedure :: at => strut_at                              !! all mass functions at one length
    procedure :: sliding_mass => strut_sliding_mass          !! mass sliding with the length, m_i + m_end [kg]
    procedure :: total_mass => strut_total_mass              !! strut mass [kg]
    procedure :: end_mass => strut_end_mass                  !! mass lumped at the lower end (footpad) [kg]
    procedure :: first_moment => strut_first_moment          !! first moment of mass about the upper joint at a length [kg m]
    procedure :: upper_first_moment => strut_upper_first_moment !! first moment of the upper (pivoting) part [kg m]
    procedure :: sliding_first_moment => strut_sliding_first_moment !! first moment of the sliding part at a length [kg m]
    procedure :: inertia => strut_inertia                    !! transverse inertia about the upper joint at a length [kg m^2]
    procedure :: inertia_rate => strut_inertia_rate          !! dJ/dL, the rate of the inertia with the length [kg m]
  end type strut_t

contains

  !> The strut made from its mass properties.
  pure function strut_from_mass(mass) result(strut)
    type(strut_mass_t), intent(in) :: mass   !! mass properties [kg, m, kg m^2]
    type(strut_t) :: strut                   !! strut mass model
    strut%mass = mass
    strut%m_s = mass%m_i + mass%m_end
    strut%m_tot = mass%m_o + strut%m_s
    strut%j_0 = mass%m_o*mass%l_o**2 + mass%i_o + mass%i_i
    strut%s_0 = mass%m_o*mass%l_o
  end function strut_from_mass

  !> All mass functions at length len (the same expressions as the single functions below).
  pure function strut_at(strut, len) result(f)
    class(strut_t), intent(in) :: strut      !! strut
    real(wp), intent(in) :: len              !! strut length [m]
    type(strut_mass_functions_t) :: f        !! its mass functions [kg, kg m, kg m^2]
    f%m_s = strut%m_s
    f%m_tot = strut%m_tot
    f%s = strut%s_0 + strut%mass%m_i*(len - strut%mass%l_i) + strut%mass%m_end*len
    f%s0 = strut%s_0
    f%s1 = strut%mass%m_i*(len - strut%mass%l_i) + strut%mass%m_end*len
    f%j = strut%j_0 + strut%mass%m_i*(len - strut%mass%l_i)**2 + strut%mass%m_end*len*len
    f%dj = 2.0_wp*strut%mass%m_i*(len - strut%mass%l_i) + 2.0_wp*strut%mass%m_end*len
  end function strut_at

  !> The mass properties the strut was made from.
  pure function strut_properties(strut) result(mass)
    class(strut_t), intent(in) :: strut      !! strut
    type(strut_mass_t) :: mass               !! mass properties [kg, m, kg m^2]
    mass = strut%mass
  end function strut_properties

  !> Sliding mass m_i + m_end.
  pure real(wp) function strut_sliding_mass(strut) result(m)
    class(strut_t), intent(in) :: strut      !! strut
    m = strut%m_s
  end function strut_sliding_mass

  !> Strut mass m_o + m_i + m_end.
  pure real(wp) function strut_total_mass(strut) result(m)
    class(strut_t), intent(in) :: strut      !! strut
    m = strut%m_tot
  end function strut_total_mass

  !> Point mass at the lower joint.
  pure real(wp) function strut_end_mass(strut) result(m)
    class(strut_t), intent(in) :: strut      !! strut
    m = strut%mass%m_end
  end function strut_end_mass

  !> First moment of mass about the upper joint, along the axis, at length len:
  !! S(L) = m_o l_o + m_i (L - l_i) + m_end L [kg m].
  pure real(wp) function strut_first_moment(strut, len) result(sm)
    class(strut_t), intent(in) :: strut      !! strut
    real(wp), intent(in) :: len              !! strut length [m]
    sm = strut%s_0 + strut%mass%m_i*(len - strut%mass%l_i) + strut%mass%m_end*len
  end function strut_first_moment

  !> First moment of the upper part, m_o l_o [kg m] (S = m_o l_o + S1).
  pure real(wp) function strut_upper_first_moment(strut) result(s0)
    class(strut_t), intent(in) :: strut      !! strut
    s0 = strut%s_0
  end function strut_upper_first_moment

  !> First moment of the sliding parts: S1(L) = m_i (L - l_i) + m_end L [kg m].
  pure real(wp) function strut_sliding_first_moment(strut, len) result(s1)
    class(strut_t), intent(in) :: strut      !! strut
    real(wp), intent(in) :: len              !! strut length [m]
    s1 = strut%mass%m_i*(len - strut%mass%l_i) + strut%mass%m_end*len
  end function strut_sliding_first_moment

  !> Transverse moment of inertia about the upper joint at length len:
  !! J(L) = j_0 + m_i (L - l_i)^2 + m_end L^2 [kg m^2].
  pure real(wp) function strut_inertia(strut, len) result(jr)
    class(strut_t), intent(in) :: strut      !! strut
    real(wp), intent(in) :: len              !! strut length [m]
    jr = strut%j_0 + strut%mass%m_i*(len - strut%mass%l_i)**2 + strut%mass%m_end*len*len
  end function strut_inertia

  !> dJ/dL = 2 m_i (L - l_i) + 2 m_end L [kg m].
  pure real(wp) function strut_inertia_rate(strut, len) result(jp)
    class(strut_t), intent(in) :: strut      !! strut
    real(wp), intent(in) :: len              !! strut length [m]
    jp = 2.0_wp*strut%mass%m_i*(len - strut%mass%l_i) + 2.0_wp*strut%mass%m_end*len
  end function strut_inertia_rate

end module landyn_strut
