//! Constants of the double-double functions, each the double-double nearest to the
//! exact value (hi = RN(c), lo = RN(c − hi)), written as bit patterns so that no decimal
//! conversion intervenes. Checked against MPFR by `b09_dd_constants_are_nearest`.

use super::Dd;

/// π.
pub const PI: Dd = Dd {
    hi: f64::from_bits(0x400921fb54442d18),
    lo: f64::from_bits(0x3ca1a62633145c07),
};
/// π/2.
pub const PI_2: Dd = Dd {
    hi: f64::from_bits(0x3ff921fb54442d18),
    lo: f64::from_bits(0x3c91a62633145c07),
};
/// π/2 as a sum of three doubles (about 161 bits), for argument reduction.
pub const PI_2_PARTS: [f64; 3] = [
    f64::from_bits(0x3ff921fb54442d18),
    f64::from_bits(0x3c91a62633145c07),
    f64::from_bits(0xb91f1976b7ed8fbc),
];
/// 2/π rounded to a double, to choose the quadrant.
pub const TWO_OVER_PI: f64 = f64::from_bits(0x3fe45f306dc9c883);
/// ln 2 as a sum of three doubles (about 161 bits), for argument reduction.
pub const LN2_PARTS: [f64; 3] = [
    f64::from_bits(0x3fe62e42fefa39ef),
    f64::from_bits(0x3c7abc9e3b39803f),
    f64::from_bits(0x3907b57a079a1934),
];
/// 1/n! for n = 0, …, 31 (exponential, sine and cosine series).
pub const INV_FACT: [Dd; 32] = [
    Dd {
        hi: f64::from_bits(0x3ff0000000000000),
        lo: f64::from_bits(0x0000000000000000),
    },
    Dd {
        hi: f64::from_bits(0x3ff0000000000000),
        lo: f64::from_bits(0x0000000000000000),
    },
    Dd {
        hi: f64::from_bits(0x3fe0000000000000),
        lo: f64::from_bits(0x0000000000000000),
    },
    Dd {
        hi: f64::from_bits(0x3fc5555555555555),
        lo: f64::from_bits(0x3c65555555555555),
    },
    Dd {
        hi: f64::from_bits(0x3fa5555555555555),
        lo: f64::from_bits(0x3c45555555555555),
    },
    Dd {
        hi: f64::from_bits(0x3f81111111111111),
        lo: f64::from_bits(0x3c01111111111111),
    },
    Dd {
        hi: f64::from_bits(0x3f56c16c16c16c17),
        lo: f64::from_bits(0xbbef49f49f49f49f),
    },
    Dd {
        hi: f64::from_bits(0x3f2a01a01a01a01a),
        lo: f64::from_bits(0x3b6a01a01a01a01a),
    },
    Dd {
        hi: f64::from_bits(0x3efa01a01a01a01a),
        lo: f64::from_bits(0x3b3a01a01a01a01a),
    },
    Dd {
        hi: f64::from_bits(0x3ec71de3a556c734),
        lo: f64::from_bits(0xbb6c154f8ddc6c00),
    },
    Dd {
        hi: f64::from_bits(0x3e927e4fb7789f5c),
        lo: f64::from_bits(0x3b3cbbc05b4fa99a),
    },
    Dd {
        hi: f64::from_bits(0x3e5ae64567f544e4),
        lo: f64::from_bits(0xbafc062e06d1f209),
    },
    Dd {
        hi: f64::from_bits(0x3e21eed8eff8d898),
        lo: f64::from_bits(0xbac2aec959e14c06),
    },
    Dd {
        hi: f64::from_bits(0x3de6124613a86d09),
        lo: f64::from_bits(0x3a8f28e0cc748ebe),
    },
    Dd {
        hi: f64::from_bits(0x3da93974a8c07c9d),
        lo: f64::from_bits(0x3a305d6f8a2efd1f),
    },
    Dd {
        hi: f64::from_bits(0x3d6ae7f3e733b81f),
        lo: f64::from_bits(0x39e1d8656b0ee8cb),
    },
    Dd {
        hi: f64::from_bits(0x3d2ae7f3e733b81f),
        lo: f64::from_bits(0x39a1d8656b0ee8cb),
    },
    Dd {
        hi: f64::from_bits(0x3ce952c77030ad4a),
        lo: f64::from_bits(0x398ac981465ddc6c),
    },
    Dd {
        hi: f64::from_bits(0x3ca6827863b97d97),
        lo: f64::from_bits(0x394eec01221a8b0b),
    },
    Dd {
        hi: f64::from_bits(0x3c62f49b46814157),
        lo: f64::from_bits(0x38f2650f61dbdcb4),
    },
    Dd {
        hi: f64::from_bits(0x3c1e542ba4020225),
        lo: f64::from_bits(0x387ea72b4afe3c2f),
    },
    Dd {
        hi: f64::from_bits(0x3bd71b8ef6dcf572),
        lo: f64::from_bits(0xb87d043ae40c4647),
    },
    Dd {
        hi: f64::from_bits(0x3b90ce396db7f853),
        lo: f64::from_bits(0xb83aebcdbd20331c),
    },
    Dd {
        hi: f64::from_bits(0x3b4761b41316381a),
        lo: f64::from_bits(0xb7d3423c7d91404f),
    },
    Dd {
        hi: f64::from_bits(0x3aff2cf01972f578),
        lo: f64::from_bits(0xb789ada5fcc1ab14),
    },
    Dd {
        hi: f64::from_bits(0x3ab3f3ccdd165fa9),
        lo: f64::from_bits(0xb7458ddadf344487),
    },
    Dd {
        hi: f64::from_bits(0x3a688e85fc6a4e5a),
        lo: f64::from_bits(0xb7071c37ebd16540),
    },
    Dd {
        hi: f64::from_bits(0x3a1d1ab1c2dccea3),
        lo: f64::from_bits(0x36a054d0c78aea14),
    },
    Dd {
        hi: f64::from_bits(0x39d0a18a2635085d),
        lo: f64::from_bits(0x366b9e2e28e1aa54),
    },
    Dd {
        hi: f64::from_bits(0x398259f98b4358ad),
        lo: f64::from_bits(0x362eaf8c39dd9bc5),
    },
    Dd {
        hi: f64::from_bits(0x3933932c5047d60e),
        lo: f64::from_bits(0x35d832b7b530a627),
    },
    Dd {
        hi: f64::from_bits(0x38e434d2e783f5bc),
        lo: f64::from_bits(0x3580b87b91be9aff),
    },
];
/// atan(j/64) for j = 0, …, 64.
pub const ATAN_TABLE: [Dd; 65] = [
    Dd {
        hi: f64::from_bits(0x0000000000000000),
        lo: f64::from_bits(0x0000000000000000),
    },
    Dd {
        hi: f64::from_bits(0x3f8fff555bbb729b),
        lo: f64::from_bits(0xbc2220c39d4dff50),
    },
    Dd {
        hi: f64::from_bits(0x3f9ffd55bba97625),
        lo: f64::from_bits(0xbc35ec431444912c),
    },
    Dd {
        hi: f64::from_bits(0x3fa7fb818430da2a),
        lo: f64::from_bits(0xbc086ef8f794f105),
    },
    Dd {
        hi: f64::from_bits(0x3faff55bb72cfdea),
        lo: f64::from_bits(0xbc3c934d86d23f1d),
    },
    Dd {
        hi: f64::from_bits(0x3fb3f59f0e7c559d),
        lo: f64::from_bits(0x3c5ac4ce285df847),
    },
    Dd {
        hi: f64::from_bits(0x3fb7ee182602f10f),
        lo: f64::from_bits(0xbc5cfb654c0c3d98),
    },
    Dd {
        hi: f64::from_bits(0x3fbbe39ebe6f07c3),
        lo: f64::from_bits(0x3c5f7b8f29a05987),
    },
    Dd {
        hi: f64::from_bits(0x3fbfd5ba9aac2f6e),
        lo: f64::from_bits(0xbc4cd37686760c17),
    },
    Dd {
        hi: f64::from_bits(0x3fc1e1fafb043727),
        lo: f64::from_bits(0xbc4b485914dacf8c),
    },
    Dd {
        hi: f64::from_bits(0x3fc3d6eee8c6626c),
        lo: f64::from_bits(0x3c661a3b0ce9281b),
    },
    Dd {
        hi: f64::from_bits(0x3fc5c9811e3ec26a),
        lo: f64::from_bits(0xbc5054ab2c010f3d),
    },
    Dd {
        hi: f64::from_bits(0x3fc7b97b4bce5b02),
        lo: f64::from_bits(0x3c5347b0b4f881ca),
    },
    Dd {
        hi: f64::from_bits(0x3fc9a6a8e96c8626),
        lo: f64::from_bits(0x3c4cf601e7b4348e),
    },
    Dd {
        hi: f64::from_bits(0x3fcb90d7529260a2),
        lo: f64::from_bits(0x3c217b10d2e0e5ab),
    },
    Dd {
        hi: f64::from_bits(0x3fcd77d5df205736),
        lo: f64::from_bits(0x3c6c648d1534597e),
    },
    Dd {
        hi: f64::from_bits(0x3fcf5b75f92c80dd),
        lo: f64::from_bits(0x3c68ab6e3cf7afbd),
    },
    Dd {
        hi: f64::from_bits(0x3fd09dc597d86362),
        lo: f64::from_bits(0x3c762e47390cb865),
    },
    Dd {
        hi: f64::from_bits(0x3fd18bf5a30bf178),
        lo: f64::from_bits(0x3c630ca4748b1bf9),
    },
    Dd {
        hi: f64::from_bits(0x3fd278372057ef46),
        lo: f64::from_bits(0xbc7077cdd36dfc81),
    },
    Dd {
        hi: f64::from_bits(0x3fd362773707ebcc),
        lo: f64::from_bits(0xbc6963a544b672d8),
    },
    Dd {
        hi: f64::from_bits(0x3fd44aa436c2af0a),
        lo: f64::from_bits(0xbc75d5e43c55b3ba),
    },
    Dd {
        hi: f64::from_bits(0x3fd530ad9951cd4a),
        lo: f64::from_bits(0xbc62566480884082),
    },
    Dd {
        hi: f64::from_bits(0x3fd614840309cfe2),
        lo: f64::from_bits(0xbc7a725715711f00),
    },
    Dd {
        hi: f64::from_bits(0x3fd6f61941e4def1),
        lo: f64::from_bits(0xbc7c63aae6f6e918),
    },
    Dd {
        hi: f64::from_bits(0x3fd7d5604b63b3f7),
        lo: f64::from_bits(0x3c769c885c2b249a),
    },
    Dd {
        hi: f64::from_bits(0x3fd8b24d394a1b25),
        lo: f64::from_bits(0x3c7b6d0ba3748fa8),
    },
    Dd {
        hi: f64::from_bits(0x3fd98cd5454d6b18),
        lo: f64::from_bits(0x3c79e6c988fd0a77),
    },
    Dd {
        hi: f64::from_bits(0x3fda64eec3cc23fd),
        lo: f64::from_bits(0xbc724dec1b50b7ff),
    },
    Dd {
        hi: f64::from_bits(0x3fdb3a911da65c6c),
        lo: f64::from_bits(0x3c7ae187b1ca5040),
    },
    Dd {
        hi: f64::from_bits(0x3fdc0db4c94ec9f0),
        lo: f64::from_bits(0xbc7cc1ce70934c34),
    },
    Dd {
        hi: f64::from_bits(0x3fdcde53432c1351),
        lo: f64::from_bits(0xbc7a2cfa4418f1ad),
    },
    Dd {
        hi: f64::from_bits(0x3fddac670561bb4f),
        lo: f64::from_bits(0x3c7a2b7f222f65e2),
    },
    Dd {
        hi: f64::from_bits(0x3fde77eb7f175a34),
        lo: f64::from_bits(0x3c70e53dc1bf3435),
    },
    Dd {
        hi: f64::from_bits(0x3fdf40dd0b541418),
        lo: f64::from_bits(0xbc6a3992dc382a23),
    },
    Dd {
        hi: f64::from_bits(0x3fe0039c73c1a40c),
        lo: f64::from_bits(0xbc8b32c949c9d593),
    },
    Dd {
        hi: f64::from_bits(0x3fe0657e94db30d0),
        lo: f64::from_bits(0xbc7d5b495f6349e6),
    },
    Dd {
        hi: f64::from_bits(0x3fe0c6145b5b43da),
        lo: f64::from_bits(0x3c5974fa13b5404f),
    },
    Dd {
        hi: f64::from_bits(0x3fe1255d9bfbd2a9),
        lo: f64::from_bits(0xbc52bdaee1c0ee35),
    },
    Dd {
        hi: f64::from_bits(0x3fe1835a88be7c13),
        lo: f64::from_bits(0x3c8c621cec00c301),
    },
    Dd {
        hi: f64::from_bits(0x3fe1e00babdefeb4),
        lo: f64::from_bits(0xbc5928df287a668f),
    },
    Dd {
        hi: f64::from_bits(0x3fe23b71e2cc9e6a),
        lo: f64::from_bits(0x3c6c421c9f38224e),
    },
    Dd {
        hi: f64::from_bits(0x3fe2958e59308e31),
        lo: f64::from_bits(0xbc709e73b0c6c087),
    },
    Dd {
        hi: f64::from_bits(0x3fe2ee628406cbca),
        lo: f64::from_bits(0x3c8c5d5e9ff0cf8d),
    },
    Dd {
        hi: f64::from_bits(0x3fe345f01cce37bb),
        lo: f64::from_bits(0x3c81021137c71102),
    },
    Dd {
        hi: f64::from_bits(0x3fe39c391cd4171a),
        lo: f64::from_bits(0xbc82304331d8bf46),
    },
    Dd {
        hi: f64::from_bits(0x3fe3f13fb89e96f4),
        lo: f64::from_bits(0x3c7ecf8b492644f0),
    },
    Dd {
        hi: f64::from_bits(0x3fe445065b795b56),
        lo: f64::from_bits(0xbc7f76d0163f79c8),
    },
    Dd {
        hi: f64::from_bits(0x3fe4978fa3269ee1),
        lo: f64::from_bits(0x3c72419a87f2a458),
    },
    Dd {
        hi: f64::from_bits(0x3fe4e8de5bb6ec04),
        lo: f64::from_bits(0x3c84a33dbeb3796c),
    },
    Dd {
        hi: f64::from_bits(0x3fe538f57b89061f),
        lo: f64::from_bits(0xbc81bb74abda520c),
    },
    Dd {
        hi: f64::from_bits(0x3fe587d81f732fbb),
        lo: f64::from_bits(0xbc75e5c9d8c5a950),
    },
    Dd {
        hi: f64::from_bits(0x3fe5d58987169b18),
        lo: f64::from_bits(0x3c60028e4bc5e7ca),
    },
    Dd {
        hi: f64::from_bits(0x3fe6220d115d7b8e),
        lo: f64::from_bits(0xbc62b785350ee8c1),
    },
    Dd {
        hi: f64::from_bits(0x3fe66d663923e087),
        lo: f64::from_bits(0xbc76ea6febe8bbba),
    },
    Dd {
        hi: f64::from_bits(0x3fe6b798920b3d99),
        lo: f64::from_bits(0xbc8a80386188c50e),
    },
    Dd {
        hi: f64::from_bits(0x3fe700a7c5784634),
        lo: f64::from_bits(0xbc78c34d25aadef6),
    },
    Dd {
        hi: f64::from_bits(0x3fe748978fba8e0f),
        lo: f64::from_bits(0x3c47b2a6165884a1),
    },
    Dd {
        hi: f64::from_bits(0x3fe78f6bbd5d315e),
        lo: f64::from_bits(0x3c8406a089803740),
    },
    Dd {
        hi: f64::from_bits(0x3fe7d528289fa093),
        lo: f64::from_bits(0x3c8560821e2f3aa9),
    },
    Dd {
        hi: f64::from_bits(0x3fe819d0b7158a4d),
        lo: f64::from_bits(0xbc7bf76229d3b917),
    },
    Dd {
        hi: f64::from_bits(0x3fe85d69576cc2c5),
        lo: f64::from_bits(0x3c66b66e7fc8b8c3),
    },
    Dd {
        hi: f64::from_bits(0x3fe89ff5ff57f1f8),
        lo: f64::from_bits(0xbc855b9a5e177a1b),
    },
    Dd {
        hi: f64::from_bits(0x3fe8e17aa99cc05e),
        lo: f64::from_bits(0xbc7ec182ab042f61),
    },
    Dd {
        hi: f64::from_bits(0x3fe921fb54442d18),
        lo: f64::from_bits(0x3c81a62633145c07),
    },
];
/// 1/(2k+1) for k = 0, …, 12 (arctangent series).
pub const INV_ODD: [Dd; 13] = [
    Dd {
        hi: f64::from_bits(0x3ff0000000000000),
        lo: f64::from_bits(0x0000000000000000),
    },
    Dd {
        hi: f64::from_bits(0x3fd5555555555555),
        lo: f64::from_bits(0x3c75555555555555),
    },
    Dd {
        hi: f64::from_bits(0x3fc999999999999a),
        lo: f64::from_bits(0xbc6999999999999a),
    },
    Dd {
        hi: f64::from_bits(0x3fc2492492492492),
        lo: f64::from_bits(0x3c62492492492492),
    },
    Dd {
        hi: f64::from_bits(0x3fbc71c71c71c71c),
        lo: f64::from_bits(0x3c5c71c71c71c71c),
    },
    Dd {
        hi: f64::from_bits(0x3fb745d1745d1746),
        lo: f64::from_bits(0xbc4745d1745d1746),
    },
    Dd {
        hi: f64::from_bits(0x3fb3b13b13b13b14),
        lo: f64::from_bits(0xbc53b13b13b13b14),
    },
    Dd {
        hi: f64::from_bits(0x3fb1111111111111),
        lo: f64::from_bits(0x3c31111111111111),
    },
    Dd {
        hi: f64::from_bits(0x3fae1e1e1e1e1e1e),
        lo: f64::from_bits(0x3c2e1e1e1e1e1e1e),
    },
    Dd {
        hi: f64::from_bits(0x3faaf286bca1af28),
        lo: f64::from_bits(0x3c4af286bca1af28),
    },
    Dd {
        hi: f64::from_bits(0x3fa8618618618618),
        lo: f64::from_bits(0x3c48618618618618),
    },
    Dd {
        hi: f64::from_bits(0x3fa642c8590b2164),
        lo: f64::from_bits(0x3c3642c8590b2164),
    },
    Dd {
        hi: f64::from_bits(0x3fa47ae147ae147b),
        lo: f64::from_bits(0xbc2eb851eb851eb8),
    },
];
