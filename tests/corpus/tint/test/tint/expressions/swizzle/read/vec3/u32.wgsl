struct S {
    v: vec3<u32>,
};

var<private> P : S;

@compute @workgroup_size(1)
fn f() {
    var    v = P.v;

    var    x = P.v.x;
    var    y = P.v.y;
    var    z = P.v.z;

    var   xx = P.v.xx;
    var   xy = P.v.xy;
    var   xz = P.v.xz;
    var   yx = P.v.yx;
    var   yy = P.v.yy;
    var   yz = P.v.yz;
    var   zx = P.v.zx;
    var   zy = P.v.zy;
    var   zz = P.v.zz;

    var  xxx = P.v.xxx;
    var  xxy = P.v.xxy;
    var  xxz = P.v.xxz;
    var  xyx = P.v.xyx;
    var  xyy = P.v.xyy;
    var  xyz = P.v.xyz;
    var  xzx = P.v.xzx;
    var  xzy = P.v.xzy;
    var  xzz = P.v.xzz;

    var  yxx = P.v.yxx;
    var  yxy = P.v.yxy;
    var  yxz = P.v.yxz;
    var  yyx = P.v.yyx;
    var  yyy = P.v.yyy;
    var  yyz = P.v.yyz;
    var  yzx = P.v.yzx;
    var  yzy = P.v.yzy;
    var  yzz = P.v.yzz;

    var  zxx = P.v.zxx;
    var  zxy = P.v.zxy;
    var  zxz = P.v.zxz;
    var  zyx = P.v.zyx;
    var  zyy = P.v.zyy;
    var  zyz = P.v.zyz;
    var  zzx = P.v.zzx;
    var  zzy = P.v.zzy;
    var  zzz = P.v.zzz;

    var xxxx = P.v.xxxx;
    var xxxy = P.v.xxxy;
    var xxxz = P.v.xxxz;
    var xxyx = P.v.xxyx;
    var xxyy = P.v.xxyy;
    var xxyz = P.v.xxyz;
    var xxzx = P.v.xxzx;
    var xxzy = P.v.xxzy;
    var xxzz = P.v.xxzz;

    var xyxx = P.v.xyxx;
    var xyxy = P.v.xyxy;
    var xyxz = P.v.xyxz;
    var xyyx = P.v.xyyx;
    var xyyy = P.v.xyyy;
    var xyyz = P.v.xyyz;
    var xyzx = P.v.xyzx;
    var xyzy = P.v.xyzy;
    var xyzz = P.v.xyzz;

    var xzxx = P.v.xzxx;
    var xzxy = P.v.xzxy;
    var xzxz = P.v.xzxz;
    var xzyx = P.v.xzyx;
    var xzyy = P.v.xzyy;
    var xzyz = P.v.xzyz;
    var xzzx = P.v.xzzx;
    var xzzy = P.v.xzzy;
    var xzzz = P.v.xzzz;

    var yxxx = P.v.yxxx;
    var yxxy = P.v.yxxy;
    var yxxz = P.v.yxxz;
    var yxyx = P.v.yxyx;
    var yxyy = P.v.yxyy;
    var yxyz = P.v.yxyz;
    var yxzx = P.v.yxzx;
    var yxzy = P.v.yxzy;
    var yxzz = P.v.yxzz;

    var yyxx = P.v.yyxx;
    var yyxy = P.v.yyxy;
    var yyxz = P.v.yyxz;
    var yyyx = P.v.yyyx;
    var yyyy = P.v.yyyy;
    var yyyz = P.v.yyyz;
    var yyzx = P.v.yyzx;
    var yyzy = P.v.yyzy;
    var yyzz = P.v.yyzz;

    var yzxx = P.v.yzxx;
    var yzxy = P.v.yzxy;
    var yzxz = P.v.yzxz;
    var yzyx = P.v.yzyx;
    var yzyy = P.v.yzyy;
    var yzyz = P.v.yzyz;
    var yzzx = P.v.yzzx;
    var yzzy = P.v.yzzy;
    var yzzz = P.v.yzzz;

    var zxxx = P.v.zxxx;
    var zxxy = P.v.zxxy;
    var zxxz = P.v.zxxz;
    var zxyx = P.v.zxyx;
    var zxyy = P.v.zxyy;
    var zxyz = P.v.zxyz;
    var zxzx = P.v.zxzx;
    var zxzy = P.v.zxzy;
    var zxzz = P.v.zxzz;

    var zyxx = P.v.zyxx;
    var zyxy = P.v.zyxy;
    var zyxz = P.v.zyxz;
    var zyyx = P.v.zyyx;
    var zyyy = P.v.zyyy;
    var zyyz = P.v.zyyz;
    var zyzx = P.v.zyzx;
    var zyzy = P.v.zyzy;
    var zyzz = P.v.zyzz;

    var zzxx = P.v.zzxx;
    var zzxy = P.v.zzxy;
    var zzxz = P.v.zzxz;
    var zzyx = P.v.zzyx;
    var zzyy = P.v.zzyy;
    var zzyz = P.v.zzyz;
    var zzzx = P.v.zzzx;
    var zzzy = P.v.zzzy;
    var zzzz = P.v.zzzz;
}
